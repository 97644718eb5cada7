// How fast the simulated world runs headless, with full stepper fidelity: every tick asks the
// firmware's step planner how many whole steps each wheel has made, integrates odometry and checks
// contacts. A "step" here is one world tick (1 ms of simulated time) for every robot in it.
import { World } from '@hal/simulation';

interface Figures {
  ticksPerS: number;
  robotTicksPerS: number;
  motorStepsPerS: number;
  realTimeFactor: number;
}

function run(robots: number, ticks: number): Figures {
  const side = Math.ceil(Math.sqrt(robots));
  const spacing = 1.5;
  const size = side * spacing + 2;
  const world = new World({
    map: { name: 'bench', arena: { width: size, height: size } },
    seed: 1,
  });
  for (let i = 0; i < robots; i += 1) {
    const x = (i % side) * spacing - ((side - 1) * spacing) / 2;
    const y = Math.floor(i / side) * spacing - ((side - 1) * spacing) / 2;
    // Circles of about 0.4 m radius: every robot moves on every tick and never touches another.
    world.addRobot({ start: { x, y, yaw: 0 } }).drive(1024, 905);
  }
  // Warm up past the acceleration ramp so the figures are for cruising robots.
  world.advance(3_000_000);
  const stepsBefore = world.robots.reduce(
    (sum, r) => sum + Math.abs(r.leftSteps) + Math.abs(r.rightSteps),
    0,
  );
  const start = process.hrtime.bigint();
  for (let i = 0; i < ticks; i += 1) world.step();
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  const stepsAfter = world.robots.reduce(
    (sum, r) => sum + Math.abs(r.leftSteps) + Math.abs(r.rightSteps),
    0,
  );
  if (world.robots.some((r) => !r.running)) throw new Error('a robot stopped during the benchmark');
  return {
    ticksPerS: ticks / seconds,
    robotTicksPerS: (ticks * robots) / seconds,
    motorStepsPerS: (stepsAfter - stepsBefore) / seconds,
    realTimeFactor: (ticks * world.tickUs) / 1e6 / seconds,
  };
}

const fmt = (n: number) =>
  n >= 1e6 ? `${(n / 1e6).toFixed(2)} M` : n >= 1e3 ? `${(n / 1e3).toFixed(1)} k` : n.toFixed(1);

for (const [robots, ticks] of [
  [1, 2_000_000],
  [100, 20_000],
] as const) {
  const f = run(robots, ticks);
  console.log(
    `${String(robots).padStart(3)} robot${robots === 1 ? ' ' : 's'}: ` +
      `${fmt(f.robotTicksPerS)} robot-steps/s (${fmt(f.ticksPerS)} world steps/s of 1 ms), ` +
      `${fmt(f.motorStepsPerS)} motor steps/s, real-time factor ${fmt(f.realTimeFactor)}x`,
  );
}
console.log(
  'anchor: a TypeScript robot simulator without a stepper model, 1 robot: ~384 k steps/s',
);

// Through the HAL in fast mode (what an agent or a test sees): validated calls, whole motions.
const { SimulationHAL } = await import('@hal/simulation');
const hal = new SimulationHAL({
  world: new World({ map: { name: 'bench', arena: { width: 40, height: 40 } } }),
});
await hal.initialize();
const calls = 200;
const simStart = hal.world.nowUs;
const wallStart = process.hrtime.bigint();
for (let i = 0; i < calls; i += 1) {
  const result =
    i % 2 === 0 ? await hal.locomotion.moveForward(5) : await hal.locomotion.rotate('left', 90);
  if (!result.success) throw new Error(`call ${i} failed: ${result.error}`);
}
const wallS = Number(process.hrtime.bigint() - wallStart) / 1e9;
const simS = (hal.world.nowUs - simStart) / 1e6;
await hal.cleanup();
console.log(
  `SimulationHAL, fast clock: ${fmt(calls / wallS)} motion calls/s ` +
    `(moveForward(5) and rotate(90) in turn), ${fmt(simS / wallS)}x real time`,
);

// The headless camera: software render plus JPEG encoding, 320x240.
{
  const { renderRobotView } = await import('@hal/simulation');
  const camHal = new SimulationHAL({ world: new World({ map: 'room' }) });
  await camHal.initialize();
  const renders = 100;
  let t = process.hrtime.bigint();
  for (let i = 0; i < renders; i += 1) renderRobotView(camHal.world, camHal.robot);
  const renderMs = Number(process.hrtime.bigint() - t) / 1e6 / renders;
  const frames = 30;
  t = process.hrtime.bigint();
  for (let i = 0; i < frames; i += 1) await camHal.vision.captureFrame();
  const frameMs = Number(process.hrtime.bigint() - t) / 1e6 / frames;
  await camHal.cleanup();
  console.log(
    `captureFrame (Node, 320x240 JPEG): ${frameMs.toFixed(1)} ms per frame ` +
      `(${(1000 / frameMs).toFixed(0)} frames/s), of which rendering ${renderMs.toFixed(1)} ms`,
  );
}
