import type { GuardedHAL } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { AgentAnswer, EvalAgent } from './agent.js';
import type { TrialBody } from './bodies/trial-body.js';
import type { Reality } from './reality.js';
import type { Task } from './task-schema.js';
import { toolBackedHal } from '@hal/tools';
import { createTrialExecutor } from './trial-executor.js';
import { scoreTrial } from './trial-score.js';
import type { TrialOptions, TrialScore, TrialTiming } from './trial-score.js';
import type { TaskVariant } from './variant.js';

/** How long an agent may take to answer once its time is up, ms. */
const ABANDON_GRACE_MS = 5000;

/** One trial, its robot ready: the HAL the agent's calls go to, and the body the checks read. */
export interface TrialSetup {
  task: Task;
  seed: number;
  agent: EvalAgent;
  variant: TaskVariant;
  /** The HAL the tools call (maybe an instrument's wrapper of the robot's). */
  hal: HardwareAbstractionLayer;
  body: TrialBody;
  reality: Reality;
  options: TrialOptions;
  /** Contacts the world reported so far (0 where nothing can tell). */
  collisions: () => number;
  /** performance.now() when the trial began. */
  started: number;
  /** The guard under `hal`, when it is on (its status goes into the score). */
  guard?: GuardedHAL | undefined;
}

/** Runs the agent on a ready robot, under the task's tools, leash, faults and budget, and scores it. */
export async function conductTrial(
  s: TrialSetup,
): Promise<{ score: TrialScore; timing: TrialTiming }> {
  const { task, agent, options, body } = s;
  const executor = createTrialExecutor(s.hal, body, task, {
    ...(options.tools === undefined ? {} : { toolNames: options.tools }),
    ...(options.leash === undefined ? {} : { leash: options.leash }),
    reality: s.reality,
    seed: s.seed,
    profile: options.profile ?? agent.toolProfile ?? 'primitives',
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
      // every agent acts through the tools: a HAL it is given is one over them, never `s.hal`
      hal: toolBackedHal(s.hal, (call) => executor.execute(call)),
      ...(agent.usesGroundTruth === true ? { truth: s.variant, truePose: () => body.pose() } : {}),
    });
    answer = await Promise.race([running, abandoned]);
  } catch (error) {
    answer = { answer: '', stopped: `the agent failed: ${(error as Error).message}` };
  } finally {
    clearTimeout(timer);
    clearTimeout(giveUp);
  }
  const score = scoreTrial({
    task,
    seed: s.seed,
    variant: s.variant,
    log: executor.log,
    pose: body.pose(),
    collisions: s.collisions(),
    estopLatched: body.emergencyStopped(),
    simSeconds: body.nowUs() / 1e6,
    answer,
    ...(s.guard === undefined ? {} : { guard: s.guard.status() }),
  });
  return {
    score,
    timing: {
      wallMs: Math.round(performance.now() - s.started),
      modelMs: Math.round(answer.modelMs ?? 0),
    },
  };
}
