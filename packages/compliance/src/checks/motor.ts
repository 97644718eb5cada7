// motor.differential: the state stream, drive commands, their refusals, and motion.
import { LATENCY_CLASSES } from '../spec.js';
import type { Check } from './check.js';
import { fail, pass } from './check.js';
import {
  changedBy,
  expectError,
  formatVerdict,
  latencyVerdict,
  rateVerdict,
  refusesVerdict,
  repliesVerdict,
  validReply,
  watched,
} from './helpers.js';
import { judgeForward, judgeTurnLeft, motionVerdict } from './motion.js';

const BAD_INPUT = ['MALFORMED', 'INVALID_PARAMETER'] as const;
const cmd = (ctx: Parameters<Check['run']>[0]) => ctx.wire.subject('differentialCmd');

export const MOTOR_CHECKS: readonly Check[] = [
  {
    capability: 'motor.differential',
    group: 'timing',
    name: 'state-rate',
    title: 'motor.differential.state streams at 10-100 Hz',
    run: (ctx) => rateVerdict(ctx, ctx.state, 'state'),
  },
  {
    capability: 'motor.differential',
    group: 'timing',
    name: 'stop-command',
    title: 'a stop command (all-zero motor.differential.cmd) round trip',
    run: (ctx) =>
      latencyVerdict(
        ctx,
        ctx.options.samples,
        LATENCY_CLASSES.lowLatency,
        () => ctx.stop(),
        validReply,
      ),
  },
  {
    capability: 'motor.differential',
    group: 'errors',
    name: 'malformed-json',
    title: 'malformed JSON gets the standard error and changes nothing',
    run: (ctx) =>
      refusesVerdict(ctx, cmd(ctx), new TextEncoder().encode('{"payload": {"linear'), BAD_INPUT),
  },
  {
    capability: 'motor.differential',
    group: 'errors',
    name: 'missing-fields',
    title: 'a drive command without its velocities gets the standard error and changes nothing',
    run: (ctx) => refusesVerdict(ctx, cmd(ctx), ctx.drive({ duration_ms: 500 }), BAD_INPUT),
  },
  {
    capability: 'motor.differential',
    group: 'errors',
    name: 'wrong-type',
    title: 'a velocity that is not a number gets the standard error and changes nothing',
    run: (ctx) =>
      refusesVerdict(
        ctx,
        cmd(ctx),
        ctx.drive({ linear_vel_m_per_s: 'fast', angular_vel_rad_per_s: 0, duration_ms: 500 }),
        BAD_INPUT,
      ),
  },
  {
    capability: 'motor.differential',
    group: 'errors',
    name: 'out-of-range',
    title: 'a velocity beyond the robot gets RANGE_EXCEEDED and changes nothing',
    run: (ctx) =>
      refusesVerdict(
        ctx,
        cmd(ctx),
        ctx.drive({ linear_vel_m_per_s: 1000, angular_vel_rad_per_s: 0, duration_ms: 500 }),
        ['RANGE_EXCEEDED'],
      ),
  },
  {
    capability: 'motor.differential',
    group: 'errors',
    name: 'neither-envelope-nor-payload',
    title:
      'a bare message that is not a valid spec payload gets the standard error and changes nothing',
    run: (ctx) =>
      refusesVerdict(
        ctx,
        cmd(ctx),
        ctx.wire.bare({ linear_vel_m_per_s: 'fast', angular_vel_rad_per_s: 0, duration_ms: 500 }),
        BAD_INPUT,
      ),
  },
  {
    capability: 'motor.differential',
    group: 'format',
    name: 'bare-command',
    title: 'a bare spec command (no envelope, as the spec example sends it) is taken as HAL v1',
    run: async (ctx) => {
      const answer = await ctx.ask(
        cmd(ctx),
        ctx.wire.bare({ linear_vel_m_per_s: 0, angular_vel_rad_per_s: 0 }),
        'ack',
        { priority: 'high' },
      );
      const problem = validReply(answer);
      if (problem !== undefined) return fail(`a bare stop command was answered ${problem}`);
      return pass('a bare stop command was acknowledged');
    },
  },
  {
    capability: 'motor.differential',
    group: 'capability',
    name: 'announced-rate',
    title: "the announced state_rate_hz is the stream's rate (within 25 %)",
    run: async (ctx) => {
      await watched(ctx, ctx.state);
      const messages = ctx.state.messages;
      const first = messages[0];
      const last = messages.at(-1);
      if (first === undefined || last === undefined || messages.length < 2) {
        return fail('no state stream to compare with');
      }
      const rateHz = ((messages.length - 1) * 1000) / (last.atMs - first.atMs);
      const announced = ctx.announcement.state_rate_hz;
      const text = `announced ${announced} Hz, measured ${rateHz.toFixed(1)} Hz`;
      return Math.abs(rateHz - announced) <= announced * 0.25
        ? pass(text, { rateHz })
        : fail(text, { rateHz });
    },
  },
  {
    capability: 'motor.differential',
    group: 'capability',
    name: 'not-implemented',
    title: 'unannounced: a drive command gets NOT_IMPLEMENTED (or no responder) and nothing moves',
    when: 'unannounced',
    run: async (ctx) => {
      let problem: string | undefined;
      const changed = await changedBy(ctx, async () => {
        const answer = await ctx.ask(
          cmd(ctx),
          ctx.drive({ linear_vel_m_per_s: 0.01, angular_vel_rad_per_s: 0, duration_ms: 500 }),
          'ack',
        );
        problem = expectError(answer, ['NOT_IMPLEMENTED'], true);
      });
      if (problem !== undefined) return fail(problem);
      if (changed !== undefined) return fail(changed);
      return pass('refused, nothing moved');
    },
  },
  {
    capability: 'motor.differential',
    group: 'state',
    name: 'drive-forward',
    title: 'a forward drive shows in the state with its velocity, moves forward, and stop ends it',
    run: (ctx) => motionVerdict(ctx, ctx.options.driveSpeedMPerS, 0, judgeForward),
  },
  {
    capability: 'motor.differential',
    group: 'state',
    name: 'turn-left',
    title: 'a positive angular velocity turns counter-clockwise in place, and stop ends it',
    run: (ctx) => motionVerdict(ctx, 0, ctx.options.turnRateRadPerS, judgeTurnLeft),
  },
  {
    capability: 'motor.differential',
    group: 'format',
    name: 'state-stream',
    title: 'state messages are valid envelopes from the device with the spec payload',
    run: async (ctx) => {
      await watched(ctx, ctx.state);
      return formatVerdict(
        ctx.state.messages.map((m) => m.inspected),
        'state messages',
      );
    },
  },
  {
    capability: 'motor.differential',
    group: 'format',
    name: 'command-replies',
    title: 'replies to drive commands are valid envelopes (acks and errors)',
    run: async (ctx) =>
      repliesVerdict(
        ctx,
        ctx.replies.filter((r) => r.subject === cmd(ctx)).map((r) => r.inspected),
        'drive replies',
      ),
  },
];
