// How fast the simulated world runs headless, in simulated robot-seconds per wall-clock second,
// for 1, 10, 100 and 1,000 robots cruising on circles, against the alternative: the simulator of
// the TypeScript robot stack this project replaces (10 ms Euler steps of DC motors, no stepper
// model; bench/alternatives/dc-motor-simulator.ts), the same number of robots, interleaved rounds.
// Ours keeps whole-step fidelity: every robot makes exactly the steps the firmware's planner
// schedules (checked at the end of every round), with odometry step by step and contact checks.
import { VelocityPlan } from '@hal/kinematics';
import { SimulationHAL, World } from '@hal/simulation';
import { DcMotorSimulator, dcArena } from './alternatives/dc-motor-simulator.js';
import { reportFigure, reportPoint } from './report/figures.js';

const SPACING = 1.5;
const LEFT_SPS = 1024;
const RIGHT_SPS = 905; // circles of about 0.8 m radius, clear of the neighbours
const ROUNDS = 5;
const MIN_ROUND_MS = 150;

function gridStart(i: number, robots: number): { x: number; y: number } {
  const side = Math.ceil(Math.sqrt(robots));
  const offset = ((side - 1) * SPACING) / 2;
  return { x: (i % side) * SPACING - offset, y: Math.floor(i / side) * SPACING - offset };
}

function arenaSide(robots: number): number {
  return Math.ceil(Math.sqrt(robots)) * SPACING + 2;
}

/** Our world: robots driving circles; advances `seconds` of simulated time per call. */
function ourWorld(robots: number) {
  const size = arenaSide(robots);
  const world = new World({
    map: { name: 'bench', arena: { width: size, height: size } },
    seed: 1,
  });
  for (let i = 0; i < robots; i += 1) {
    world.addRobot({ start: { ...gridStart(i, robots), yaw: 0 } }).drive(LEFT_SPS, RIGHT_SPS);
  }
  world.advance(3_000_000); // past the acceleration ramp
  const plan = new VelocityPlan(LEFT_SPS, RIGHT_SPS, 512);
  return {
    run(seconds: number) {
      world.advance(seconds * 1e6);
    },
    /** Every robot still running, on the planner's schedule to the step. */
    check() {
      const want = plan.stepsAt(world.nowUs);
      for (const r of world.robots) {
        if (!r.running) throw new Error(`${r.id} stopped: ${r.motion?.outcome}`);
        if (r.leftSteps !== want.left || r.rightSteps !== want.right) {
          throw new Error(
            `${r.id} is at ${r.leftSteps}/${r.rightSteps} steps, the plan at ${want.left}/${want.right}`,
          );
        }
      }
    },
  };
}

/** The alternative: one DC-motor simulator per robot, stepped every 10 ms. */
function altWorld(robots: number, snapshots = true) {
  const arena = dcArena(arenaSide(robots), arenaSide(robots));
  let states = 0;
  const onState = () => {
    states += 1;
  };
  const sims = Array.from({ length: robots }, (_, i) => {
    const sim = new DcMotorSimulator(arena, { ...gridStart(i, robots), rotation: 0 }, onState);
    sim.drive(255, Math.round((255 * RIGHT_SPS) / LEFT_SPS));
    sim.snapshots = snapshots;
    return sim;
  });
  return {
    run(seconds: number) {
      const steps = Math.round(seconds * 100);
      for (let s = 0; s < steps; s += 1) for (const sim of sims) sim.step(0.01);
    },
    check() {
      if (snapshots && states === 0) throw new Error('the alternative never stepped');
    },
  };
}

/** Robot-seconds per wall second: runs chunks of `chunkS` simulated seconds for at least MIN_ROUND_MS. */
function measure(sim: { run(s: number): void }, robots: number, chunkS: number): number {
  let simulated = 0;
  const start = performance.now();
  let elapsed = 0;
  while (elapsed < MIN_ROUND_MS) {
    sim.run(chunkS);
    simulated += chunkS;
    elapsed = performance.now() - start;
  }
  return (simulated * robots) / (elapsed / 1000);
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] ?? 0;
const fmt = (n: number) =>
  n >= 1e6 ? `${(n / 1e6).toFixed(2)} M` : n >= 1e3 ? `${(n / 1e3).toFixed(1)} k` : n.toFixed(1);

console.log(
  `simulated robot-seconds per wall second, median of ${ROUNDS} interleaved rounds ` +
    `(ours: event stepping, whole steps; alternative: 10 ms DC-motor steps, no stepper model)`,
);
for (const robots of [1, 10, 100, 1000]) {
  const ours = ourWorld(robots);
  const alt = altWorld(robots);
  const bare = altWorld(robots, false);
  const chunk = robots >= 1000 ? 0.5 : robots >= 100 ? 2 : 10;
  const altChunk = robots >= 100 ? 0.05 : 0.5;
  measure(ours, robots, chunk); // warm up both
  measure(alt, robots, altChunk);
  measure(bare, robots, altChunk);
  const a: number[] = [];
  const b: number[] = [];
  const c: number[] = [];
  for (let round = 0; round < ROUNDS; round += 1) {
    a.push(measure(ours, robots, chunk));
    b.push(measure(alt, robots, altChunk));
    c.push(measure(bare, robots, altChunk * 4));
    ours.check();
    alt.check();
  }
  const o = median(a);
  const x = median(b);
  const y = median(c);
  console.log(
    `${String(robots).padStart(5)} robot${robots === 1 ? ' ' : 's'}: ours ${fmt(o).padStart(8)}, ` +
      `alternative ${fmt(x).padStart(8)} robot-s/s: ${(o / x).toFixed(1)}x ` +
      `(its physics alone, without the state it publishes every step: ${fmt(y)}, ` +
      `${(o / y).toFixed(1)}x); the whole world runs ${fmt(o / robots)}x real time`,
  );
  const label = `${robots} robot${robots === 1 ? '' : 's'}`;
  const note =
    "the alternative is a model of the replaced stack's simulator written here (bench/alternatives), not its code";
  reportFigure({
    bench: 'simulation',
    name: `${label}, simulated robot-seconds per wall second`,
    value: o,
    unit: 'robot-s/s',
    better: 'higher',
    alternative: { name: '10 ms DC-motor simulator, no stepper model', value: x },
    goal: robots === 1000 ? 'faster than real time' : robots === 10 ? undefined : '>= 10x',
    ...(robots === 10 ? {} : { met: robots === 1000 ? o / robots > 1 : o / x >= 10 }),
    note,
  });
  reportFigure({
    bench: 'simulation',
    name: `${label}, against the alternative's physics step only`,
    value: o,
    unit: 'robot-s/s',
    better: 'higher',
    alternative: { name: 'the same, without its per-step state snapshot', value: y },
    note,
  });
  reportFigure({
    bench: 'simulation',
    name: `${label}, whole world against real time`,
    value: o / robots,
    unit: 'x real time',
    better: 'higher',
  });
  for (const [series, value] of [
    ['event stepping (ours)', o],
    ['10 ms DC-motor simulator', x],
  ] as const) {
    reportPoint({
      plot: 'simulation-robots',
      title: 'Simulation speed by robot count',
      series,
      x: robots,
      y: value,
      xLabel: 'robots in one world',
      yLabel: 'simulated robot-seconds per wall second',
      logX: true,
      logY: true,
    });
  }
}

// Through the HAL in fast mode (what an agent or a test sees): validated calls, whole motions.
const hal = new SimulationHAL({
  world: new World({ map: { name: 'bench', arena: { width: 40, height: 40 } } }),
});
await hal.initialize();
const calls = 400;
const simStart = hal.world.nowUs;
const wallStart = performance.now();
for (let i = 0; i < calls; i += 1) {
  const result =
    i % 2 === 0 ? await hal.locomotion.moveForward(5) : await hal.locomotion.rotate('left', 90);
  if (!result.success) throw new Error(`call ${i} failed: ${result.error}`);
}
const wallS = (performance.now() - wallStart) / 1000;
const simS = (hal.world.nowUs - simStart) / 1e6;
await hal.cleanup();
console.log(
  `SimulationHAL, fast clock: ${fmt(calls / wallS)} motion calls/s ` +
    `(moveForward(5) and rotate(90) in turn), ${fmt(simS / wallS)}x real time`,
);
reportFigure({
  bench: 'simulation',
  name: 'SimulationHAL fast-clock motion calls (moveForward(5), rotate(90))',
  value: calls / wallS,
  unit: 'calls/s',
  better: 'higher',
});
