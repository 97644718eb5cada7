import { guardHal, Perception, withCameraScan } from '@hal/perception';
import { SimulationHAL, World } from '@hal/simulation';
import type { EvalAgent } from './agent.js';
import { simulatedBody } from './bodies/simulated-body.js';
import { conductTrial } from './conduct-trial.js';
import { bodyErrorOf, trialReality } from './reality.js';
import type { Task } from './task-schema.js';
import type { TrialOptions, TrialScore, TrialTiming } from './trial-score.js';
import { realiseTask, variantSeed } from './variant.js';

export type {
  InstrumentedHal,
  TrialInfo,
  TrialOptions,
  TrialScore,
  TrialTiming,
} from './trial-score.js';

/** Runs one trial of `task` with `seed` in the simulator: a fresh world, the agent, the checks. */
export async function runTrial(
  task: Task,
  seed: number,
  agent: EvalAgent,
  options: TrialOptions = {},
): Promise<{ score: TrialScore; timing: TrialTiming }> {
  const started = performance.now();
  const variant = realiseTask(task, seed);
  const world = new World({ map: variant.map, seed });
  const reality = trialReality(options.reality, task.reality);
  // the body's errors are drawn from the trial's seed, apart from the call loss's draws
  const bodyError = bodyErrorOf(reality, (variantSeed(task.id, seed) ^ 0x5bd1e995) >>> 0);
  const sim = new SimulationHAL({
    world,
    start: variant.start,
    features: { ...task.world.sensors, ...options.sensors },
    ...(reality.rangeNoiseM > 0 ? { rangeSensors: { noiseSigma: reality.rangeNoiseM } } : {}),
    ...(bodyError === undefined ? {} : { bodyError }),
  });
  let collisions = 0;
  world.events.on('collision', (e) => {
    if (e.robotId === sim.robot.id) collisions += 1;
  });
  // the guard sits under the agent's tools (and under a recorder: what is recorded is the agent's)
  const guard = options.guard === false ? undefined : guardHal(sim, options.guard ?? {});
  // scan answers from what the robot can know: its range sensors and its camera's look
  const seeing =
    sim.getDeviceInfo().camera === undefined
      ? (guard ?? sim)
      : withCameraScan(guard ?? sim, new Perception(sim));
  const instrumented = await options.instrument?.(seeing, {
    task,
    variant,
    seed,
    trial: options.trial ?? 0,
    agent: agent.name,
    on: 'simulator',
    nowUs: () => world.nowUs,
  });
  const hal = instrumented?.hal ?? seeing;
  try {
    await hal.initialize();
    return await conductTrial({
      task,
      seed,
      agent,
      variant,
      hal,
      body: simulatedBody(sim),
      reality,
      options,
      collisions: () => collisions,
      started,
      guard,
    });
  } finally {
    await hal.cleanup();
    await instrumented?.close();
  }
}
