import { guardHal, Perception, withCameraScan } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import { errorMessage } from '@hal/types';
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

/**
 * Runs one trial of `task` on `robot`. A robot that can be staged in the task's world runs it
 * there, judged from its body's true pose ({@link EvalRobot.stage}); any other is scored from
 * its own reports (its odometry), starting where it stands. The link's knobs (loss, latency)
 * apply, the simulator's body and sensor knobs do not: the robot has its own. An e-stop left
 * latched is reset after the trial, so the next one starts free.
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
  if (stage !== undefined) {
    // staged in the seed's variant of the world, its start included
    const variant = realiseTask(task, seed);
    const staged = await reach(robot, () => stage(variant));
    const judged = stagedBody(staged.hal, staged, variant, robot.timeScale ?? 1);
    try {
      return await conductOnRobot(
        { task, seed, agent, robot, options, started, variant },
        {
          raw: staged.hal,
          // its scan answers from the camera, as the simulator's does without range sensors
          seeing: (under) => withCameraScan(under, new Perception(staged.hal)),
          body: () => Promise.resolve(judged.body),
          collisions: judged.collisions,
        },
      );
    } finally {
      judged.close();
      await staged.close();
    }
  }
  if (!runsOnRobot(task))
    throw new EvalError(
      'CONFIG',
      `${task.id} cannot run on ${robot.name}: its checks need the simulator's ground truth`,
    );
  const raw = await reach(robot, () => robot.open());
  return await conductOnRobot(
    { task, seed, agent, robot, options, started, variant: realiseAtOrigin(task, seed) },
    {
      raw,
      body: () => reportedBody(raw, robot.timeScale ?? 1),
      collisions: () => 0,
    },
  );
}

/** What the robot answers, or ROBOT naming it. */
async function reach<T>(robot: EvalRobot, open: () => Promise<T>): Promise<T> {
  try {
    return await open();
  } catch (error) {
    throw new EvalError('ROBOT', `${robot.name}: ${errorMessage(error)}`, { cause: error });
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

/** One trial on a robot: what it is, and where. */
interface RobotTrial {
  task: Task;
  seed: number;
  agent: EvalAgent;
  robot: EvalRobot;
  options: TrialOptions;
  started: number;
  variant: TaskVariant;
}

/** How a robot is seen and judged in a trial. */
interface RobotJudging {
  /** The robot's own HAL, not yet initialised. */
  raw: HardwareAbstractionLayer;
  /** What the agent's tools see through, over the guard. Default the guard itself. */
  seeing?: (under: HardwareAbstractionLayer) => HardwareAbstractionLayer;
  /** The body the checks read, made once the robot is initialised. */
  body: () => Promise<TrialBody>;
  collisions: () => number;
}

/** Runs the agent on the robot under the guard and the tools, and scores it. */
async function conductOnRobot(
  t: RobotTrial,
  j: RobotJudging,
): Promise<{ score: TrialScore; timing: TrialTiming }> {
  const { task, robot, options, raw } = { ...t, ...j };
  let body: TrialBody | undefined;
  /** Whether a latch at the end is this trial's own (an injected or the agent's e-stop). */
  let latchedByTrial = false;
  // the guard sits under the agent's tools (and under a recorder: what is recorded is the agent's)
  const guard = options.guard === false ? undefined : guardHal(raw, options.guard ?? {});
  const seeing = j.seeing?.(guard ?? raw) ?? guard ?? raw;
  const instrumented = await options.instrument?.(seeing, {
    task,
    variant: t.variant,
    seed: t.seed,
    trial: options.trial ?? 0,
    agent: t.agent.name,
    on: robot.name,
    nowUs: () => body?.nowUs() ?? 0,
  });
  const hal = instrumented?.hal ?? seeing;
  try {
    body = await reach(robot, async () => {
      await hal.initialize();
      return await j.body();
    });
    // a latch the harness did not set is someone's: it is not reset here
    if (raw.safety.isEmergencyStopped())
      throw new EvalError(
        'ROBOT',
        `${robot.name}: the emergency stop is engaged; reset it on the robot before the run`,
      );
    latchedByTrial = true;
    return await conductTrial({
      task,
      seed: t.seed,
      agent: t.agent,
      variant: t.variant,
      hal,
      body,
      reality: linkRealityOf(options, task),
      options,
      collisions: j.collisions,
      started: t.started,
      guard,
    });
  } finally {
    if (latchedByTrial && raw.isReady() && raw.safety.isEmergencyStopped())
      await raw.safety.resetEmergencyStop().catch(() => undefined);
    await hal.cleanup().catch(() => undefined);
    await instrumented?.close();
  }
}
