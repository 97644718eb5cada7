// safety: the e-stop latches (health, state, refused motion) until an explicit reset clears it.
import type { RunContext } from '../context.js';
import { describeAnswer } from '../context.js';
import { LATENCY_CLASSES, announces } from '../spec.js';
import type { Check, Verdict } from './check.js';
import { fail, pass, sleep } from './check.js';
import { changedBy, expectError, latencyVerdict, repliesVerdict, validReply } from './helpers.js';

const estop = (ctx: RunContext) =>
  ctx.ask(
    ctx.wire.subject('estop'),
    ctx.wire.envelope('hal/safety/estop/cmd/1.0', { reason: 'compliance check' }),
    'ack',
    { priority: 'high' },
  );

/** Resets the e-stop the runner holds; says what went wrong, if anything. */
export async function resetEstop(ctx: RunContext): Promise<string | undefined> {
  const answer = await ctx.ask(
    ctx.wire.subject('estopReset'),
    ctx.wire.envelope('hal/safety/estop/reset/1.0', {}),
    'ack',
    { priority: 'high' },
  );
  if (answer.inspected?.payload === undefined)
    return `the reset was answered ${describeAnswer(answer)}`;
  ctx.estopHeld = false;
  return undefined;
}

async function latchVerdict(ctx: RunContext): Promise<Verdict> {
  const motor = announces(ctx.caps, 'motor.differential');
  const initial = await ctx.health();
  if (initial === undefined) return fail('no valid health reply to start from');
  if (initial.status === 'emergency_stopped') {
    return fail(
      "the device was already emergency-stopped: the runner does not reset someone else's e-stop",
    );
  }
  const answer = await estop(ctx);
  ctx.estopHeld = true;
  if (answer.inspected?.payload === undefined)
    return fail(`the e-stop was answered ${describeAnswer(answer)}`);
  if ((await ctx.health())?.status !== 'emergency_stopped') {
    return fail('after the e-stop, health.status is not emergency_stopped');
  }
  if (motor && (await ctx.state.next(1500, (s) => s.emergency_stopped)) === undefined) {
    return fail('after the e-stop, the state stream never showed emergency_stopped: true');
  }
  if (motor) {
    let problem: string | undefined;
    const changed = await changedBy(ctx, async () => {
      const drive = await ctx.ask(
        ctx.wire.subject('differentialCmd'),
        ctx.drive({
          linear_vel_m_per_s: ctx.options.driveSpeedMPerS,
          angular_vel_rad_per_s: 0,
          duration_ms: 500,
        }),
        'ack',
      );
      problem = expectError(drive, ['EMERGENCY_STOPPED']);
    });
    if (problem !== undefined) return fail(`a drive while e-stopped: ${problem}`);
    if (changed !== undefined) return fail(`a drive while e-stopped: ${changed}`);
  }
  await sleep(200);
  if ((await ctx.health())?.status !== 'emergency_stopped')
    return fail('the e-stop did not stay latched');
  const resetProblem = await resetEstop(ctx);
  if (resetProblem !== undefined) return fail(resetProblem);
  const status = (await ctx.health())?.status;
  if (status === 'emergency_stopped' || status === undefined) {
    return fail(`after the reset, health.status is ${String(status)}`);
  }
  if (motor && (await ctx.state.next(1500, (s) => !s.emergency_stopped)) === undefined) {
    return fail('after the reset, the state stream still shows emergency_stopped: true');
  }
  return pass(
    `latched in health${motor ? ', state and a refused drive (EMERGENCY_STOPPED)' : ''}; the reset cleared it`,
  );
}

export const SAFETY_CHECKS: readonly Check[] = [
  {
    capability: 'safety',
    group: 'state',
    name: 'estop-latches',
    title: 'an e-stop latches (health, state, drive refused) until safety.estop.reset',
    run: latchVerdict,
  },
  {
    capability: 'safety',
    group: 'timing',
    name: 'estop',
    title: 'safety.estop.cmd round trip (Priority: high), each followed by a reset',
    run: (ctx) =>
      latencyVerdict(
        ctx,
        Math.min(ctx.options.samples, 5),
        LATENCY_CLASSES.lowLatency,
        async () => {
          const answer = await estop(ctx);
          ctx.estopHeld = true;
          return answer;
        },
        validReply,
        async () => {
          const problem = await resetEstop(ctx);
          if (problem !== undefined) throw new Error(problem);
        },
      ),
  },
  {
    capability: 'safety',
    group: 'format',
    name: 'estop-replies',
    title: 'replies to e-stop and reset are valid envelopes',
    run: async (ctx) =>
      repliesVerdict(
        ctx,
        ctx.replies
          .filter(
            (r) =>
              r.subject === ctx.wire.subject('estop') ||
              r.subject === ctx.wire.subject('estopReset'),
          )
          .map((r) => r.inspected),
        'e-stop replies',
      ),
  },
  {
    capability: 'safety',
    group: 'capability',
    name: 'not-implemented',
    title: 'unannounced: safety.estop.cmd gets NOT_IMPLEMENTED (or no responder)',
    when: 'unannounced',
    run: async (ctx) => {
      const answer = await estop(ctx);
      if (answer.inspected?.payload !== undefined) ctx.estopHeld = true;
      const problem = expectError(answer, ['NOT_IMPLEMENTED'], true);
      return problem === undefined ? pass(describeAnswer(answer)) : fail(problem);
    },
  },
];
