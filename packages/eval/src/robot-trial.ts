import { guardHal, Perception, withCameraScan } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { EvalAgent } from './agent.js';
import { reportedBody } from './bodies/reported-body.js';
import { stagedBody } from './bodies/staged-body.js';
import type { TruePoseSource } from './bodies/staged-body.js';
import type { TrialBody } from './bodies/trial-body.js';
import { conductTrial } from './conduct-trial.js';
import { EvalError } from './errors.js';
import { trialReality } from './reality.js';
import type { Task } from './task-schema.js';
import type { TrialOptions, TrialScore, TrialTiming } from './trial-score.js';
import { realiseAtOrigin, realiseTask } from './variant.js';
import type { TaskVariant } from './variant.js';

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
  /**
   * Puts the robot into a task's world, where it can be (an emulated cube with its camera: the
   * camera renders the variant's world from where the body truly is, placed at its start, and the
   * body's wheels tell the judge where it truly is). Such a robot runs every task, judged from
   * that truth as the simulator's trials are. Without it, a robot runs only the tasks judged from
   * its own reports ({@link runsOnRobot}).
   */
  stage?(variant: TaskVariant): Promise<StagedRobot>;
}

/** A robot put into a task's world for one trial. */
export interface StagedRobot extends TruePoseSource {
  /**
   * A HAL for the trial, not yet initialised, whose poses are in the world's frame (it starts
   * at the variant's start, as PhysicalHAL's `startPose` places it), its camera seeing the world.
   */
  readonly hal: HardwareAbstractionLayer;
  /** Takes the world down (its camera); the robot itself stays. */
  close(): Promise<void>;
}

/** The checks that need only the robot's own pose. */
const REPORTED_CHECKS: ReadonlySet<string> = new Set(['displacement', 'return']);

/**
 * Whether a task can run on `robot`: every task on a robot that can be staged in its world;
 * otherwise only those judged from what a robot reports: nothing in its world but the robot
 * (the `empty` map, no objects), and checks of the robot's pose only (displacement, return).
 */
export function runsOnRobot(task: Task, robot?: EvalRobot): boolean {
  if (robot?.stage !== undefined) return true;
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
  const stage = robot.stage?.bind(robot);
  if (stage !== undefined) return await runStagedTrial(task, seed, agent, robot, stage, options);
  if (!runsOnRobot(task))
    throw new EvalError(
      'CONFIG',
      `${task.id} cannot run on ${robot.name}: its checks need the simulator's ground truth`,
    );
  const linkReality = linkRealityOf(options, task);
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

/** The link's knobs of a trial (loss, latency): a robot has its own body and sensors. */
function linkRealityOf(options: TrialOptions, task: Task) {
  return {
    ...trialReality(options.reality, task.reality),
    rangeNoiseM: 0,
    wheelDiameterErrorPct: 0,
    wheelSlipPct: 0,
    odometryNoisePct: 0,
  };
}

/**
 * A trial on a robot staged in the task's world (the seed's variant, its start included),
 * judged from the body's true pose as a simulated trial is from the simulator's. Its scan
 * answers from the camera, as the simulator's does for a robot without range sensors.
 */
async function runStagedTrial(
  task: Task,
  seed: number,
  agent: EvalAgent,
  robot: EvalRobot,
  stage: (variant: TaskVariant) => Promise<StagedRobot>,
  options: TrialOptions,
): Promise<{ score: TrialScore; timing: TrialTiming }> {
  const started = performance.now();
  const variant = realiseTask(task, seed);
  let staged: StagedRobot;
  try {
    staged = await stage(variant);
  } catch (error) {
    throw new EvalError('ROBOT', `${robot.name}: ${message(error)}`, { cause: error });
  }
  const raw = staged.hal;
  const judged = stagedBody(raw, staged, variant, robot.timeScale ?? 1);
  let latchedByTrial = false;
  const guard = options.guard === false ? undefined : guardHal(raw, options.guard ?? {});
  const seeing = withCameraScan(guard ?? raw, new Perception(raw));
  const instrumented = await options.instrument?.(seeing, {
    task,
    variant,
    seed,
    trial: options.trial ?? 0,
    agent: agent.name,
    on: robot.name,
    nowUs: () => judged.body.nowUs(),
  });
  const hal = instrumented?.hal ?? seeing;
  try {
    try {
      await hal.initialize();
    } catch (error) {
      throw new EvalError('ROBOT', `${robot.name}: ${message(error)}`, { cause: error });
    }
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
      body: judged.body,
      reality: linkRealityOf(options, task),
      options,
      collisions: judged.collisions,
      started,
      guard,
    });
  } finally {
    if (latchedByTrial && raw.isReady() && raw.safety.isEmergencyStopped())
      await raw.safety.resetEmergencyStop().catch(() => undefined);
    await hal.cleanup().catch(() => undefined);
    await instrumented?.close();
    judged.close();
    await staged.close();
  }
}
