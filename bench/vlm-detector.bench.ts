// A vision model as perception's detector, against the simulator's truth: seeded scenes of one to
// three coloured boxes and pillars in view (0.5..2 m, within the field of view), each frame sent to
// the model at HAL_VLM_BASE_URL (HAL_VLM_MODEL; HAL_VLM_API_KEY when it needs one) and placed on
// the floor by FramePerceiver, beside colour segmentation on the same frames. Reports recall,
// precision (an object counts when its colour is right and it lands within 0.3 m), the world
// position error of matched objects (median, p95), the model's time per frame, and the frames it
// failed. Needs an endpoint: without HAL_VLM_BASE_URL and HAL_VLM_MODEL it says so and measures
// nothing. HAL_VLM_BOX_UNITS=per-mille for models that give boxes in 0..1000 (Qwen2-VL, Gemini);
// HAL_VLM_SCENES (default 12), HAL_VLM_TIMEOUT_MS (default 60000).
import { cameraProjection, pixelOfPoint } from '@hal/kinematics';
import { COLOUR_NAMES, FramePerceiver, VisionModelDetector } from '@hal/perception';
import type { ColourName, Percept, VisionModelDetectorOptions } from '@hal/perception';
import { encodeJpeg, renderRobotView, SeededRandom, World } from '@hal/simulation';
import type { WorldMapInput } from '@hal/simulation';
import { V1_CAMERA, errorMessage } from '@hal/types';
import { percentile, reportFigure } from './report/figures.js';

const BENCH = 'vlm-detector';
const baseUrl = process.env['HAL_VLM_BASE_URL'] ?? '';
const model = process.env['HAL_VLM_MODEL'] ?? '';
if (baseUrl === '' || model === '') {
  console.log(
    `${BENCH}: no vision model to ask: set HAL_VLM_BASE_URL (e.g. http://127.0.0.1:11434/v1) and HAL_VLM_MODEL; nothing measured`,
  );
  process.exit(0);
}
const SCENES = Number(process.env['HAL_VLM_SCENES'] ?? 12);
const MATCH_M = 0.3;
const units = process.env['HAL_VLM_BOX_UNITS'] === 'per-mille' ? 'per-mille' : 'pixels';

const HEX: Record<ColourName, string> = {
  red: '#d62828',
  orange: '#f77f00',
  yellow: '#f4c430',
  green: '#2a9d3f',
  blue: '#1d4ed8',
  purple: '#7b2cbf',
};
type Obstacle = NonNullable<WorldMapInput['obstacles']>[number];
interface Truth {
  colour: ColourName;
  kind: 'box' | 'pillar';
  x: number;
  y: number;
}

const projection = cameraProjection(V1_CAMERA);

/** Whether all of an object at robot-frame (x, y) is inside the image (robot at the origin). */
function inView(x: number, y: number, reach: number): boolean {
  for (const z of [0, 0.3]) {
    for (let k = 0; k < 8; k += 1) {
      const a = (k / 8) * 2 * Math.PI;
      const p = pixelOfPoint(projection, {
        x: x + reach * Math.cos(a),
        y: y + reach * Math.sin(a),
        z,
      });
      if (p === undefined || p.u < 1 || p.u > V1_CAMERA.width - 1 || p.v > V1_CAMERA.height - 1)
        return false;
    }
  }
  return true;
}

/** A seeded scene: the robot at the origin facing +x, one to three objects of distinct colours. */
function scene(seed: number): { obstacles: Obstacle[]; truth: Truth[] } {
  const random = new SeededRandom(seed);
  const count = 1 + Math.floor(random.next() * 3);
  const colours = [...COLOUR_NAMES].sort(() => random.next() - 0.5);
  const obstacles: Obstacle[] = [];
  const truth: Truth[] = [];
  for (let tries = 0; tries < 200 && truth.length < count; tries += 1) {
    const distance = 0.5 + 1.5 * random.next();
    const bearing = ((random.next() - 0.5) * 50 * Math.PI) / 180;
    const x = distance * Math.cos(bearing);
    const y = distance * Math.sin(bearing);
    if (!inView(x, y, 0.22)) continue;
    // Nothing hidden behind another: their bearings apart by more than their half-widths.
    const half = Math.asin(0.22 / distance);
    const hidden = truth.some((t) => {
      const d = Math.hypot(t.x, t.y);
      return Math.abs(Math.atan2(t.y, t.x) - bearing) < half + Math.asin(0.22 / d) + 0.03;
    });
    if (hidden) continue;
    const colour = colours[truth.length] ?? 'red';
    const kind = random.next() < 0.5 ? 'box' : 'pillar';
    obstacles.push(
      kind === 'box'
        ? { kind: 'box', x, y, width: 0.3, depth: 0.3, height: 0.3, color: HEX[colour] }
        : { kind: 'cylinder', x, y, radius: 0.15, height: 0.3, color: HEX[colour] },
    );
    truth.push({ colour, kind, x, y });
  }
  return { obstacles, truth };
}

interface Tally {
  truths: number;
  found: number;
  reported: number;
  correct: number;
  errorsM: number[];
  failures: number;
  ms: number[];
}
const tally = (): Tally => ({
  truths: 0,
  found: 0,
  reported: 0,
  correct: 0,
  errorsM: [],
  failures: 0,
  ms: [],
});

/** Scores one percept against the truth: each object matched to the truth of its colour. */
function score(t: Tally, truth: Truth[], percept: Percept): void {
  t.truths += truth.length;
  t.reported += percept.objects.length;
  const matched = new Set<Truth>();
  for (const object of percept.objects) {
    const near = truth.find(
      (o) =>
        !matched.has(o) &&
        o.colour === object.colour &&
        Math.hypot(o.x - object.world.x, o.y - object.world.y) <= MATCH_M,
    );
    if (near === undefined) continue;
    matched.add(near);
    t.correct += 1;
    t.errorsM.push(Math.hypot(near.x - object.world.x, near.y - object.world.y));
  }
  t.found += matched.size;
}

const options: VisionModelDetectorOptions = {
  baseUrl,
  model,
  boxUnits: units,
  timeoutMs: Number(process.env['HAL_VLM_TIMEOUT_MS'] ?? 60_000),
};
const apiKey = process.env['HAL_VLM_API_KEY'];
if (apiKey !== undefined && apiKey !== '') options.apiKey = apiKey;
const detector = new VisionModelDetector(options);
const vlm = new FramePerceiver({ detector });
const colour = new FramePerceiver();
const byModel = tally();
const byColour = tally();
const pose = { x: 0, y: 0, yaw: 0 };
const failures: string[] = [];

for (let seed = 1; seed <= SCENES; seed += 1) {
  const { obstacles, truth } = scene(seed);
  const world = new World({ map: { name: `vlm-${seed}`, obstacles } });
  const frame = `data:image/jpeg;base64,${Buffer.from(
    await encodeJpeg(renderRobotView(world, world.addRobot({ start: pose })), 85),
  ).toString('base64')}`;
  score(byColour, truth, await colour.perceive(frame, pose));
  const started = performance.now();
  try {
    const percept = await vlm.perceive(frame, pose);
    byModel.ms.push(performance.now() - started);
    score(byModel, truth, percept);
    const said = percept.objects.map((o) => o.label).join(', ') || 'nothing';
    console.log(
      `scene ${seed}: ${truth.map((o) => `${o.colour} ${o.kind}`).join(', ')} -> ${said}`,
    );
  } catch (error) {
    byModel.failures += 1;
    byModel.truths += truth.length;
    failures.push(`scene ${seed}: ${errorMessage(error)}`);
  }
}
for (const line of failures) console.log(line);

const pct = (a: number, b: number) => (b === 0 ? 0 : Math.round((1000 * a) / b) / 10);
const cm = (samples: number[], p: number) => Math.round(percentile(samples, p) * 1000) / 10;
const note = `${model} at ${new URL(baseUrl).host}, boxes in ${units}, ${SCENES} scenes`;
const alternative = (value: number) => ({ name: 'colour segmentation', value });
console.log(
  `${model}: recall ${pct(byModel.found, byModel.truths)} %, precision ${pct(byModel.correct, byModel.reported)} %, ` +
    `error median ${cm(byModel.errorsM, 50)} cm p95 ${cm(byModel.errorsM, 95)} cm, ` +
    `${Math.round(percentile(byModel.ms, 50))} ms a frame, ${byModel.failures} failed; ` +
    `colour segmentation: recall ${pct(byColour.found, byColour.truths)} %, error median ${cm(byColour.errorsM, 50)} cm`,
);
reportFigure({
  bench: BENCH,
  name: 'objects found (recall)',
  value: pct(byModel.found, byModel.truths),
  unit: '%',
  better: 'higher',
  alternative: alternative(pct(byColour.found, byColour.truths)),
  note,
});
reportFigure({
  bench: BENCH,
  name: 'objects reported that are there (precision)',
  value: pct(byModel.correct, byModel.reported),
  unit: '%',
  better: 'higher',
  alternative: alternative(pct(byColour.correct, byColour.reported)),
  note,
});
if (byModel.errorsM.length > 0) {
  reportFigure({
    bench: BENCH,
    name: 'world position error median',
    value: cm(byModel.errorsM, 50),
    unit: 'cm',
    better: 'lower',
    alternative: alternative(cm(byColour.errorsM, 50)),
    note,
  });
  reportFigure({
    bench: BENCH,
    name: 'world position error p95',
    value: cm(byModel.errorsM, 95),
    unit: 'cm',
    better: 'lower',
    alternative: alternative(cm(byColour.errorsM, 95)),
    note,
  });
}
if (byModel.ms.length > 0) {
  reportFigure({
    bench: BENCH,
    name: 'time per frame (median)',
    value: Math.round(percentile(byModel.ms, 50)),
    unit: 'ms',
    better: 'lower',
    note,
  });
}
reportFigure({
  bench: BENCH,
  name: 'frames the model failed',
  value: byModel.failures,
  unit: 'frames',
  better: 'lower',
  note,
});
