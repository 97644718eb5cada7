// The state consistency checks of motor.differential: a small, short drive shows in the state
// stream with the commanded velocities, the pose moves the right way, and a stop ends it.
import type { DifferentialState } from '@hal/nats';
import { angleDifference } from '@hal/types';
import type { RunContext } from '../context.js';
import { describeAnswer } from '../context.js';
import type { Verdict } from './check.js';
import { fail, pass, sleep } from './check.js';

const close = (seen: number, want: number, floor: number) =>
  Math.abs(seen - want) <= Math.max(Math.abs(want) * 0.15, floor);
const LINEAR_FLOOR = 0.002;
const ANGULAR_FLOOR = 0.03;
const STILL = 1e-3;

/**
 * Drives at (linear, angular) for at most `motionMs` (the device stops by itself then), waits
 * until the state stream shows those velocities, drives 300 ms more, stops, and judges the pose
 * change with `judge` (undefined: right, else what is wrong).
 */
export async function motionVerdict(
  ctx: RunContext,
  linear: number,
  angular: number,
  judge: (before: DifferentialState, after: DifferentialState) => string | undefined,
): Promise<Verdict> {
  const before = await ctx.freshState(1500);
  if (before === undefined) return fail('no state on the state stream to start from');
  if (before.emergency_stopped) return fail('the device is emergency-stopped: not moving it');
  const motionMs = ctx.options.motionMs;
  const reply = ctx.ask(
    ctx.wire.subject('differentialCmd'),
    ctx.drive({
      linear_vel_m_per_s: linear,
      angular_vel_rad_per_s: angular,
      duration_ms: motionMs,
      stop_action: 'brake',
    }),
    'ack',
    { timeoutMs: motionMs + ctx.options.requestTimeoutMs },
  );
  // A refusal ends the wait at once; an acknowledgement (some devices reply at the start,
  // ours at the end of the motion) does not.
  const refused = reply.then((answer) =>
    answer.inspected?.payload !== undefined ? new Promise<never>(() => undefined) : answer,
  );
  const started = performance.now();
  const seen = await Promise.race([
    ctx.state.next(
      motionMs,
      (s) =>
        close(s.linear_vel_m_per_s, linear, LINEAR_FLOOR) &&
        close(s.angular_vel_rad_per_s, angular, ANGULAR_FLOOR),
    ),
    refused,
  ]);
  if (seen === undefined || !('x_m' in seen)) {
    await ctx.stop();
    if (seen !== undefined) return fail(`the drive command was answered ${describeAnswer(seen)}`);
    const fastest = ctx.state
      .since(started)
      .map((m) => m.inspected.payload)
      .filter((s): s is DifferentialState => s !== undefined)
      .reduce(
        (a, s) =>
          Math.abs(s.linear_vel_m_per_s) + Math.abs(s.angular_vel_rad_per_s) >
          Math.abs(a.linear_vel_m_per_s) + Math.abs(a.angular_vel_rad_per_s)
            ? s
            : a,
        before,
      );
    return fail(
      `the state never showed linear ${linear} m/s, angular ${angular} rad/s within ${motionMs} ms (fastest seen: ${fastest.linear_vel_m_per_s.toFixed(4)} m/s, ${fastest.angular_vel_rad_per_s.toFixed(3)} rad/s)`,
    );
  }
  const seenAfterMs = performance.now() - started;
  await sleep(300);
  const stopAt = performance.now();
  const stopAnswer = await ctx.stop();
  if (stopAnswer.inspected?.payload === undefined) {
    return fail(`the stop command was answered ${describeAnswer(stopAnswer)}`);
  }
  const stopped = await ctx.state.next(
    1500,
    (s) => Math.abs(s.linear_vel_m_per_s) < STILL && Math.abs(s.angular_vel_rad_per_s) < STILL,
  );
  const stoppedAfterMs = performance.now() - stopAt;
  if (stopped === undefined) return fail('the state still showed motion 1500 ms after the stop');
  if (stopAt - started + stoppedAfterMs >= motionMs) {
    return fail(`the motion ended only when its duration_ms ran out, not at the stop`);
  }
  await sleep(300);
  const later = await ctx.freshState();
  if (later !== undefined && Math.hypot(later.x_m - stopped.x_m, later.y_m - stopped.y_m) > 0.002) {
    return fail('the robot kept moving after the state showed it stopped');
  }
  await reply; // bounded by its timeout; its outcome (ack or interrupted) is not judged
  const problem = judge(before, stopped);
  if (problem !== undefined) return fail(problem);
  const dx = stopped.x_m - before.x_m;
  const dy = stopped.y_m - before.y_m;
  return pass(
    `state showed the command after ${seenAfterMs.toFixed(0)} ms and the stop after ${stoppedAfterMs.toFixed(0)} ms; moved ${(Math.hypot(dx, dy) * 1000).toFixed(1)} mm, turned ${angleDifference(stopped.yaw_rad, before.yaw_rad).toFixed(3)} rad`,
  );
}

/** Forward: the pose moved along the heading it had, and barely turned. */
export function judgeForward(
  before: DifferentialState,
  after: DifferentialState,
): string | undefined {
  const dx = after.x_m - before.x_m;
  const dy = after.y_m - before.y_m;
  const along = dx * Math.cos(before.yaw_rad) + dy * Math.sin(before.yaw_rad);
  const across = -dx * Math.sin(before.yaw_rad) + dy * Math.cos(before.yaw_rad);
  const turned = angleDifference(after.yaw_rad, before.yaw_rad);
  if (along < 0.003)
    return `driving forward moved ${(along * 1000).toFixed(1)} mm along the heading (want > 3 mm forward)`;
  if (Math.abs(across) > along / 2)
    return `driving forward moved ${(across * 1000).toFixed(1)} mm sideways`;
  if (Math.abs(turned) > 0.1) return `driving straight turned ${turned.toFixed(3)} rad`;
  return undefined;
}

/** Counter-clockwise (REP-103): yaw grew, and the robot turned in place. */
export function judgeTurnLeft(
  before: DifferentialState,
  after: DifferentialState,
): string | undefined {
  const turned = angleDifference(after.yaw_rad, before.yaw_rad);
  const moved = Math.hypot(after.x_m - before.x_m, after.y_m - before.y_m);
  if (turned < 0.05)
    return `a positive angular velocity turned ${turned.toFixed(3)} rad (want > 0.05 rad counter-clockwise)`;
  if (moved > 0.005) return `turning in place moved the robot ${(moved * 1000).toFixed(1)} mm`;
  return undefined;
}
