// The guard's latency, in real time: a SimulationHAL on a real-time clock, camera only (no range
// sensors), guarded by @hal/perception's guardHal with its defaults (stand-off 0.1 m, a look every
// 100 ms). The robot is told to move 1.5 m forward across the empty arena; while it drives, an
// obstacle (another robot, a dark 10 cm cube) appears 0.25..0.45 m ahead of its front. Measured
// per trial: from the start of the capture of the frame the guard stopped on to the stop command,
// and to the robot at rest (the real-time simulator steps its clock every 16 ms, so rest is seen
// to that grain); and the gap left (a contact would end it at 0). The capture's time includes the
// simulator rendering and encoding the frame (on the cube: the camera's exposure and transfer).
//
// GUARD_TRIALS=N sets the number of trials (default 30).
import { guardHal } from '@hal/perception';
import { SimulationHAL, World } from '@hal/simulation';
import { delay } from '@hal/types';
import { percentile, reportFigure } from './report/figures.js';

const TRIALS = Number(process.env.GUARD_TRIALS ?? 30);
const BODY_RADIUS_M = 0.07;

interface Trial {
  frameToStopCallMs: number;
  frameToRestMs: number;
  gapM: number;
  code: string;
}

/** Waits until `done()` or `timeoutMs`, polling every millisecond; the time it held, or undefined. */
async function until(done: () => boolean, timeoutMs: number): Promise<number | undefined> {
  const limit = performance.now() + timeoutMs;
  while (performance.now() < limit) {
    if (done()) return performance.now();
    await delay(1);
  }
  return undefined;
}

async function trial(index: number): Promise<Trial | undefined> {
  const world = new World({ map: 'empty' });
  const sim = new SimulationHAL({
    world,
    clock: 'realtime',
    features: { rangeSensors: false },
    start: { x: -1.8, y: 0, yaw: 0 },
  });
  await sim.initialize();
  const guarded = guardHal(sim);
  const robot = sim.robot;
  let obstacleX = Number.POSITIVE_INFINITY;
  const gap = () => obstacleX - BODY_RADIUS_M - (robot.x + BODY_RADIUS_M);
  const captures: number[] = [];
  let stopCalledAt: number | undefined;
  const capture = sim.vision.captureFrame.bind(sim.vision);
  sim.vision.captureFrame = () => {
    captures.push(performance.now());
    return capture();
  };
  const stop = sim.locomotion.stop.bind(sim.locomotion);
  sim.locomotion.stop = () => {
    stopCalledAt ??= performance.now();
    return stop();
  };
  try {
    const motion = guarded.locomotion.moveForward(150);
    // The obstacle appears while the robot drives: after 0.4..1.2 s, 0.25..0.45 m ahead.
    await until(() => robot.running, 5000);
    await delay(400 + ((index * 277) % 800));
    const ahead = 0.25 + ((index * 0.061) % 0.2);
    obstacleX = robot.x + BODY_RADIUS_M + ahead + BODY_RADIUS_M;
    world.addRobot({ start: { x: obstacleX, y: 0, yaw: Math.PI } });
    const result = await motion;
    const restAt = await until(() => !robot.running, 5000);
    if (stopCalledAt === undefined || restAt === undefined) {
      console.log(
        `  trial ${index}: no stop (${result.code ?? 'success'}), gap ${gap().toFixed(3)} m`,
      );
      return undefined;
    }
    const called = stopCalledAt;
    const tripFrame = captures.filter((t) => t <= called).at(-1) ?? called;
    return {
      frameToStopCallMs: called - tripFrame,
      frameToRestMs: restAt - tripFrame,
      gapM: gap(),
      code: result.code ?? 'success',
    };
  } finally {
    await sim.cleanup();
    world.stopRealtime();
  }
}

const trials: Trial[] = [];
let misses = 0;
for (let i = 0; i < TRIALS; i += 1) {
  const t = await trial(i);
  if (t === undefined) misses += 1;
  else trials.push(t);
}
const stat = (xs: number[]) =>
  `p50 ${percentile(xs, 50).toFixed(1)} ms, p99 ${percentile(xs, 99).toFixed(1)} ms`;
const frameToStopCall = trials.map((t) => t.frameToStopCallMs);
const frameToRest = trials.map((t) => t.frameToRestMs);
const gaps = trials.map((t) => t.gapM);
const collisions = trials.filter((t) => t.gapM <= 0.005).length;
const codes = [...new Set(trials.map((t) => t.code))].join(', ');
console.log(
  `guard (camera only, defaults: stand-off 0.1 m, 10 looks/s), ${TRIALS} trials, an obstacle ` +
    `appearing 0.25..0.45 m ahead while driving; answers: ${codes}; ${misses} trials not stopped`,
);
console.log(`  from the frame it stopped on to the stop command: ${stat(frameToStopCall)}`);
console.log(`  from that frame to the robot at rest (16 ms sim ticks): ${stat(frameToRest)}`);
console.log(
  `  gap left to the obstacle: min ${(100 * Math.min(...gaps)).toFixed(1)} cm, median ` +
    `${(100 * percentile(gaps, 50)).toFixed(1)} cm; ${collisions} contacts`,
);
reportFigure({
  bench: 'perception-guard',
  name: 'guard: frame showing the obstacle to robot at rest, p99',
  value: percentile(frameToRest, 99),
  unit: 'ms',
  better: 'lower',
  note:
    `${trials.length} trials, camera only, real-time simulator (rest seen to its 16 ms ticks); ` +
    `p50 ${percentile(frameToRest, 50).toFixed(1)} ms`,
});
reportFigure({
  bench: 'perception-guard',
  name: 'guard: frame showing the obstacle to the stop command, p99',
  value: percentile(frameToStopCall, 99),
  unit: 'ms',
  better: 'lower',
  goal: '< 100 ms (one frame at 10 fps)',
  met: percentile(frameToStopCall, 99) < 100,
});
reportFigure({
  bench: 'perception-guard',
  name: 'guard: contacts with the obstacle',
  value: collisions,
  unit: 'trials',
  better: 'lower',
  goal: '0',
  met: collisions === 0 && misses === 0,
  note: `${trials.length + misses} trials; min gap left ${(100 * Math.min(...gaps)).toFixed(1)} cm`,
});
