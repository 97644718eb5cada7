import { guardHal } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { EvalAgent } from './agent.js';
import { reportedBody } from './bodies/reported-body.js';
import type { TrialBody } from './bodies/trial-body.js';
import { conductTrial } from './conduct-trial.js';
import { EvalError } from './errors.js';
import { RealitySchema } from './reality.js';
import type { Task } from './task-schema.js';
import type { TrialOptions, TrialScore, TrialTiming } from './trial-score.js';
import { realiseAtOrigin } from './variant.js';

/**
 * A robot the tasks can also run on (the emulated cube through PhysicalHAL, or the real one),
 * seen only through what it reports. `@hal/eval` builds no HAL of its own: the caller opens it.
 */
export interface EvalRobot {
  /** Its name in reports: its agents' rows read `oracle@NAME`. */
  readonly name: string;
  /** How much faster than real time its clock runs (an emulator's `--time-scale`). Default 1. */
  readonly timeScale?: number;
  /**
   * A HAL for one trial, not yet initialised: a fresh session, whose odometry starts at the
   * robot's origin when it is initialised (as PhysicalHAL's does).
   */
  open(): Promise<HardwareAbstractionLayer>;
}

/** The checks that need only the robot's own pose. */
const REPORTED_CHECKS: ReadonlySet<string> = new Set(['displacement', 'return']);

/**
 * Whether a task can be judged from what a robot reports: nothing in its world but the robot
 * (the `empty` map, no objects), and checks of the robot's pose only (displacement, return).
 */
export function runsOnRobot(task: Task): boolean {
  return (
    task.world.map === 'empty' &&
    task.world.objects.length === 0 &&
    task.checks.every((c) => REPORTED_CHECKS.has(c.kind))
  );
}

const message = (error: unknown) => (error instanceof Error ? error.message : String(error));

/**
 * Runs one trial of `task` on `robot`, scored from the robot's own reports (its odometry). The
 * robot starts where it stands; the link's knobs (loss, latency) apply, the simulator's body and
 * sensor knobs do not: the robot has its own. An e-stop left latched is reset after the trial, so
 * the next one starts free.
 */
export async function runRobotTrial(
  task: Task,
  seed: number,
  agent: EvalAgent,
  robot: EvalRobot,
  options: TrialOptions = {},
): Promise<{ score: TrialScore; timing: TrialTiming }> {
  const started = performance.now();
  if (!runsOnRobot(task))
    throw new EvalError(
      'CONFIG',
      `${task.id} cannot run on ${robot.name}: its checks need the simulator's ground truth`,
    );
  const linkReality = {
    ...RealitySchema.parse(options.reality ?? {}),
    rangeNoiseM: 0,
    wheelDiameterErrorPct: 0,
    wheelSlipPct: 0,
    odometryNoisePct: 0,
  };
  const variant = realiseAtOrigin(task, seed);
  let raw: HardwareAbstractionLayer;
  try {
    raw = await robot.open();
  } catch (error) {
    throw new EvalError('ROBOT', `${robot.name}: ${message(error)}`, { cause: error });
  }
  let body: TrialBody | undefined;
  /** Whether a latch at the end is this trial's own (an injected or the agent's e-stop). */
  let latchedByTrial = false;
  // the guard sits under the agent's tools (and under a recorder: what is recorded is the agent's)
  const guard = options.guard === false ? undefined : guardHal(raw, options.guard ?? {});
  const instrumented = await options.instrument?.(guard ?? raw, {
    task,
    variant,
    seed,
    trial: options.trial ?? 0,
    agent: agent.name,
    on: robot.name,
    nowUs: () => body?.nowUs() ?? 0,
  });
  const hal = instrumented?.hal ?? guard ?? raw;
  try {
    try {
      await hal.initialize();
      body = await reportedBody(raw, robot.timeScale ?? 1);
    } catch (error) {
      throw new EvalError('ROBOT', `${robot.name}: ${message(error)}`, { cause: error });
    }
    // a latch the harness did not set is someone's: it is not reset here
    if (raw.safety.isEmergencyStopped())
      throw new EvalError(
        'ROBOT',
        `${robot.name}: the emergency stop is engaged; reset it on the robot before the run`,
      );
    latchedByTrial = true;
    return await conductTrial({
      task,
      seed,
      agent,
      variant,
      hal,
      body,
      reality: linkReality,
      options,
      collisions: () => 0,
      started,
      guard,
    });
  } finally {
    if (latchedByTrial && raw.isReady() && raw.safety.isEmergencyStopped())
      await raw.safety.resetEmergencyStop().catch(() => undefined);
    await hal.cleanup().catch(() => undefined);
    await instrumented?.close();
  }
}
