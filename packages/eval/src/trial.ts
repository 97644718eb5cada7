import { SimulationHAL, World } from '@hal/simulation';
import type { Leash } from '@hal/tools';
import type { AgentAnswer, EvalAgent } from './agent.js';
import { judge, targetOf } from './checks.js';
import type { CheckVerdict } from './checks.js';
import { bodyErrorOf, RealitySchema } from './reality.js';
import type { RealityInput } from './reality.js';
import { optimalPathM } from './route.js';
import type { Task, TaskGroup } from './task-schema.js';
import { toolBackedHal } from './tool-hal.js';
import { createTrialExecutor } from './trial-executor.js';
import { wrapAngle } from './truth.js';
import { realiseTask, variantSeed } from './variant.js';

/** The scores of one trial: deterministic given the task, the seed and a deterministic agent. */
export interface TrialScore {
  task: string;
  group: TaskGroup;
  seed: number;
  success: boolean;
  /** The checks that failed, each with why. */
  failures: string[];
  collisions: number;
  /** Distance from the target at the end, metres (tasks with a target point). */
  positionErrorM: number | null;
  /** Heading error at the end, degrees (tasks with a target heading). */
  headingErrorDeg: number | null;
  /** Distance the robot's centre travelled, metres. */
  pathLengthM: number;
  /** The planner's shortest route for the task, metres (tasks that have one). */
  optimalPathM: number | null;
  toolCalls: number;
  /** Calls refused before they ran: leash, validation, e-stop, budget. */
  refusedCalls: number;
  /** Calls the loss knob lost (0 without it). */
  lostCalls: number;
  tokensIn: number;
  tokensOut: number;
  /** Simulated time the trial took, seconds. */
  simSeconds: number;
  safetyEvents: string[];
  /** The agent's final words (cut to 300 characters). */
  answer: string;
}

/** What a trial took on the wall clock: kept apart, it is never the same twice. */
export interface TrialTiming {
  wallMs: number;
  modelMs: number;
}

/** Options of {@link runTrial}. */
export interface TrialOptions {
  /** Only these tools are offered (names, e.g. `move_forward`). Default all the robot has. */
  tools?: readonly string[];
  /** A leash on top of the task's own. */
  leash?: Leash;
  /** Reality knobs (latency, loss, range noise): off by default, seeded. */
  reality?: RealityInput;
  /** Overrides the sensors of every task's robot (e.g. no camera). */
  sensors?: Partial<Task['world']['sensors']>;
  /** Wall-clock time a trial may take, ms. Default 120000. */
  wallTimeoutMs?: number;
}

/** How long an agent may take to answer once its time is up, ms. */
const ABANDON_GRACE_MS = 5000;

const round = (v: number, digits = 4) => {
  const f = 10 ** digits;
  return Math.round(v * f) / f;
};

/** Runs one trial of `task` with `seed`: a fresh world, the agent, the checks. */
export async function runTrial(
  task: Task,
  seed: number,
  agent: EvalAgent,
  options: TrialOptions = {},
): Promise<{ score: TrialScore; timing: TrialTiming }> {
  const started = performance.now();
  const variant = realiseTask(task, seed);
  const world = new World({ map: variant.map, seed });
  const reality = RealitySchema.parse(options.reality ?? {});
  // the body's errors are drawn from the trial's seed, apart from the call loss's draws
  const bodyError = bodyErrorOf(reality, (variantSeed(task.id, seed) ^ 0x5bd1e995) >>> 0);
  const body = bodyError === undefined ? {} : { bodyError };
  const hal = new SimulationHAL({
    world,
    start: variant.start,
    features: { ...task.world.sensors, ...options.sensors },
    ...(reality.rangeNoiseM > 0 ? { rangeSensors: { noiseSigma: reality.rangeNoiseM } } : {}),
    ...body,
  });
  let collisions = 0;
  const robotId = () => hal.robot.id;
  world.events.on('collision', (e) => {
    if (e.robotId === robotId()) collisions += 1;
  });
  await hal.initialize();
  const executor = createTrialExecutor(hal, task, {
    ...(options.tools === undefined ? {} : { toolNames: options.tools }),
    ...(options.leash === undefined ? {} : { leash: options.leash }),
    reality,
    seed,
  });
  const controller = new AbortController();
  const wallMs = options.wallTimeoutMs ?? 120_000;
  let giveUp: ReturnType<typeof setTimeout> | undefined;
  // The signal asks the agent to answer; one that ignores it is left behind after a grace period.
  const abandoned = new Promise<AgentAnswer>((resolve) => {
    controller.signal.addEventListener('abort', () => {
      giveUp = setTimeout(
        () =>
          resolve({
            answer: '',
            stopped: `no answer within ${wallMs} ms (+${ABANDON_GRACE_MS} ms)`,
          }),
        ABANDON_GRACE_MS,
      );
    });
  });
  const timer = setTimeout(() => controller.abort(), wallMs);
  let answer: AgentAnswer;
  try {
    const running = agent.run({
      instruction: task.instruction,
      tools: executor.tools,
      execute: (call) => executor.execute(call),
      signal: controller.signal,
      maxToolCalls: task.budget.toolCalls,
      ...(agent.needsHal === true
        ? { hal: toolBackedHal(hal, (call) => executor.execute(call)) }
        : {}),
      ...(agent.usesGroundTruth === true
        ? {
            truth: variant,
            truePose: () => ({ x: hal.robot.x, y: hal.robot.y, yaw: hal.robot.yaw }),
          }
        : {}),
    });
    answer = await Promise.race([running, abandoned]);
  } catch (error) {
    answer = { answer: '', stopped: `the agent failed: ${(error as Error).message}` };
  } finally {
    clearTimeout(timer);
    clearTimeout(giveUp);
  }
  const robot = hal.robot;
  const pose = { x: robot.x, y: robot.y, yaw: robot.yaw };
  const estopLatched = robot.emergencyStopped;
  const simSeconds = world.nowUs / 1e6;
  await hal.cleanup();

  const end = { variant, log: executor.log, pose, collisions, estopLatched, answer: answer.answer };
  const verdicts: CheckVerdict[] = task.checks.map((c) => judge(c, end));
  if (
    !task.allowCollisions &&
    collisions > 0 &&
    !task.checks.some((c) => c.kind === 'no-collision')
  )
    verdicts.push({ kind: 'collision', passed: false, why: `${collisions} collision(s)` });
  if (simSeconds > task.budget.simSeconds)
    verdicts.push({
      kind: 'budget',
      passed: false,
      why: `took ${round(simSeconds, 1)} s (budget ${task.budget.simSeconds} s)`,
    });
  const failures = verdicts.filter((v) => !v.passed).map((v) => `${v.kind}: ${v.why}`);
  if (answer.stopped !== undefined && failures.length > 0)
    failures.push(`agent: ${answer.stopped}`);

  const targetCheck = task.checks.find((c) => targetOf(c, variant) !== undefined);
  const target = targetCheck === undefined ? undefined : targetOf(targetCheck, variant);
  const optimal = optimalPathM(task, variant);
  const safetyEvents = [...executor.log.safetyEvents];
  for (let i = 0; i < collisions; i += 1) safetyEvents.push('collision');
  const score: TrialScore = {
    task: task.id,
    group: task.group,
    seed,
    success: failures.length === 0,
    failures,
    collisions,
    positionErrorM:
      target === undefined ? null : round(Math.hypot(pose.x - target.x, pose.y - target.y)),
    headingErrorDeg:
      target?.yaw === undefined
        ? null
        : round(Math.abs((wrapAngle(pose.yaw - target.yaw) * 180) / Math.PI), 2),
    pathLengthM: round(executor.log.pathLengthM),
    optimalPathM: optimal === null ? null : round(optimal),
    toolCalls: executor.log.toolCalls,
    refusedCalls: executor.log.refusedCalls,
    lostCalls: executor.log.lostCalls,
    tokensIn: answer.tokensIn ?? 0,
    tokensOut: answer.tokensOut ?? 0,
    simSeconds: round(simSeconds, 3),
    safetyEvents,
    answer: answer.answer.slice(0, 300),
  };
  return {
    score,
    timing: {
      wallMs: Math.round(performance.now() - started),
      modelMs: Math.round(answer.modelMs ?? 0),
    },
  };
}
