// One e-stop trial against the emulator, measured on the robot's own clock: a long move runs, a
// get_status is pending with its replies lost, and emergencyStop() is called. The time of the
// call is read on the robot's clock (the emulator says where its uptime starts on this machine's
// monotonic clock), the time the wheels stopped comes from the estop reply, and the steps made
// after the call are those the move's step schedule (the firmware's, to the microsecond) has
// between the two instants: what the board's step interrupt makes. (The emulator, on a loaded
// machine, may make them a little late; that delay is inside the measured time anyway.) Shared by tests/physical/estop.test.ts and
// bench/estop.bench.ts.
import { MovePlan } from '@hal/kinematics';
import type { PhysicalHAL } from '@hal/physical';
import type { HALToolResult } from '@hal/types';
import type { Emulator } from './emulator.js';
import type { FaultProxy, Faults } from './fault-proxy.js';
import { seedRequest } from './robot-probe.js';

/** The acceleration the trials set, steps/s^2: the move cruises within 10 ms. */
export const TRIAL_ACCELERATION = 100_000;

/** How the e-stop travels: the safety lane, or behind the pending request (the old queue). */
export type EstopPath = 'lane' | 'queued';

export interface EstopTrial {
  path: EstopPath;
  /** From the emergencyStop() call to the wheels stopping, robot clock, ms. */
  robotLatencyMs: number;
  /** Master-wheel steps scheduled between the call and the stop. */
  stepsAfterCall: number;
  /** From the call to emergencyStop() resolving, host clock, ms. */
  hostLatencyMs: number;
  /**
   * Whether emergencyStop() had resolved while the stuck status request was still waiting: the
   * stop was not queued behind it (an order, which a loaded machine's delays do not change).
   */
  stoppedBeforeStatus: boolean;
  estop: HALToolResult;
  move: HALToolResult;
  /** The HAL for the next trial: a fresh one when the trial abandoned the stuck request. */
  hal: PhysicalHAL;
}

/** Reads the robot's uptime, µs, through the emulator's monotonic origin (time scale 1 only). */
export function robotClock(emulator: Emulator): () => number {
  const ready = emulator.events.find((e) => e.event === 'ready');
  const origin = Number(ready?.['uptime_origin_us']);
  if (!Number.isFinite(origin) || Number(ready?.['time_scale']) !== 1) {
    throw new Error('the emulator must run at time scale 1 and report uptime_origin_us');
  }
  return () => Number(process.hrtime.bigint() / 1000n) - origin;
}

/** Sets the emulator's acceleration with one seed-style datagram (no session is disturbed). */
export async function setAcceleration(port: number, acceleration: number): Promise<void> {
  await seedRequest(port, { cmd: 'set_config', acceleration_steps_per_s2: acceleration }, 2000);
}

const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/**
 * Runs one trial: a 40 cm move, `runMs` of driving, a get_status whose next `lostReplies`
 * replies the proxy drops, then the e-stop by `path`; then resets the stop.
 *
 * Without `reopen`, the trial waits for the stuck get_status to end (its resends, 500 ms each)
 * before it resets the stop through the same session. With `reopen`, a lane trial does not: once
 * the stop is measured and the move has resolved, it closes the HAL, abandoning the request, and
 * resets the stop through the fresh session `reopen` opens (the trial's `hal` is the one to use
 * next). What is measured is the same; only the wait after it goes. A queued trial has waited for
 * the request by then anyway. With `faults`, the link is clean between trials and loses by
 * `faults` (both ways) from the stuck request until the move has resolved: the stop meets the same
 * lossy link, and the setup and the reset around it no longer wait for resends.
 */
export async function estopTrial(options: {
  hal: PhysicalHAL;
  emulator: Emulator;
  proxy: FaultProxy;
  now: () => number;
  path: EstopPath;
  runMs: number;
  lostReplies: number;
  reopen?: () => Promise<PhysicalHAL>;
  faults?: Faults;
}): Promise<EstopTrial> {
  const { emulator, proxy, now, path } = options;
  let hal = options.hal;
  // a lossy link can lose every resend of one request: wait until the session is open again
  for (let waited = 0; hal.linkState !== 'connected'; waited += 10) {
    if (waited > 15_000) throw new Error(`the link stayed ${hal.linkState}`);
    await sleep(10);
  }
  const startedBefore = emulator.events.filter((e) => e.event === 'move_started').length;
  const moving = hal.locomotion.moveForward(40);
  const started = await Promise.race([
    emulator.waitFor(
      (e) =>
        e.event === 'move_started' &&
        emulator.events.filter((x) => x.event === 'move_started').indexOf(e) >= startedBefore,
      10_000,
    ),
    moving.then((move) => {
      throw new Error(`the move ended before it started: ${move.code} ${move.error}`);
    }),
  ]);
  await sleep(options.runMs);
  if (options.faults !== undefined) {
    proxy.setFaults({ toRobot: options.faults, toHost: options.faults });
  }
  proxy.dropNextReplies(options.lostReplies);
  let statusSettled = false;
  const pending = hal
    .refreshStatus()
    .catch(() => undefined)
    .finally(() => {
      statusSettled = true;
    });
  await sleep(1); // the status request is out
  const calledHost = performance.now();
  const calledRobotUs = now();
  const estop =
    path === 'lane'
      ? await hal.safety.emergencyStop('trial')
      : await pending.then(() => hal.safety.emergencyStop('trial'));
  const hostLatencyMs = performance.now() - calledHost;
  const stoppedBeforeStatus = !statusSettled;
  const move = await moving;
  if (options.faults !== undefined) proxy.setFaults({ toRobot: {}, toHost: {} });
  if (options.reopen === undefined || path === 'queued') {
    await pending;
  } else {
    await hal.cleanup(); // the stuck request is abandoned: it rejects at once
    proxy.stopDropping(); // a reply still to drop would be the fresh session's
    hal = await options.reopen();
  }
  const stoppedUs = Number(estop.data?.['robotEstopUs']);
  const plan = new MovePlan(
    Number(started['left_steps']),
    Number(started['right_steps']),
    Number(started['speed']),
    TRIAL_ACCELERATION,
  );
  const startUs = Number(started['t_us']);
  const steps = (us: number) => plan.stepsAt(Math.max(0, us - startUs)).left;
  // a lossy link may lose every resend of one request: try the reset again
  let reset = await hal.safety.resetEmergencyStop();
  for (let i = 0; i < 3 && !reset.success; i++) reset = await hal.safety.resetEmergencyStop();
  if (!reset.success) throw new Error(`reset failed: ${reset.code} ${reset.error}`);
  return {
    path,
    robotLatencyMs: (stoppedUs - calledRobotUs) / 1000,
    stepsAfterCall: steps(stoppedUs) - steps(calledRobotUs),
    hostLatencyMs,
    stoppedBeforeStatus,
    estop,
    move,
    hal,
  };
}

/** The p-th percentile of `samples`. */
export function percentile(samples: number[], p: number): number {
  const sorted = [...samples].sort((a, b) => a - b);
  return (
    sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil((p / 100) * sorted.length) - 1))] ?? 0
  );
}
