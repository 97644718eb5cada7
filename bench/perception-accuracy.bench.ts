// How well perception sees, against the simulator's truth: many seeded worlds (the empty, room
// and obstacles maps with task-like coloured objects added), robot poses not inside anything;
// each frame rendered by the simulator's camera, encoded as JPEG (as captureFrame does) and
// perceived by FramePerceiver. Objects: recall, precision, world position error, kind; free
// space: each world's frames fused into a fresh OccupancyGrid, compared with the true map.
// Twice: with the reality knobs off (believed pose = true pose) and on (the eval's wheel knobs
// --wheel-diameter-error 2 --wheel-slip 5 --odometry-noise 2: the robot drives its last 0.4..0.9 m
// to each pose and turns onto its heading with that body error, and perception places what it
// sees from the odometry pose it reports, while the frame is rendered from where it truly is).
//
// PERCEPTION_WORLDS=N sets the number of worlds (default 200), 5 poses each; PERCEPTION_EXPLAIN=1
// prints every false positive, miss and error over 15 cm with what the detector said.
import { cameraProjection } from '@hal/kinematics';
import { OccupancyGrid } from '@hal/navigation';
import { FramePerceiver, integrateFreeSpace, toWorld } from '@hal/perception';
import type { SeenObject } from '@hal/perception';
import { encodeJpeg, renderRobotView, SeededRandom, World } from '@hal/simulation';
import type { BodyErrorInput } from '@hal/simulation';
import { cameraModel } from '@hal/types';
import { percentile, reportFigure } from './report/figures.js';
import { makeScene, placeRobot } from './perception-scenes.js';
import type { Scene } from './perception-scenes.js';
import { colouredSolids, covered, distanceToSolid, viewOf } from './perception-truth.js';
import type { SolidView } from './perception-truth.js';

const WORLDS = Number(process.env.PERCEPTION_WORLDS ?? 200);
const POSES = 5;
const TRUTH_RANGE_M = 2;
const MATCH_M = 0.5;
const REALITY: Omit<BodyErrorInput, 'seed'> = {
  wheelDiameterErrorPct: 2,
  wheelSlipPct: 5,
  odometryNoisePct: 2,
};

const projection = cameraProjection(cameraModel());
const pct = (part: number, whole: number) => (whole === 0 ? 0 : (100 * part) / whole);
const cm = (m: number) => (100 * m).toFixed(1);
const EXPLAIN = process.env.PERCEPTION_EXPLAIN === '1';

function describe(o: SeenObject): string {
  const at = `${o.distanceM.toFixed(2)} m ${o.bearingDeg.toFixed(0)} deg`;
  return `${o.colour} ${o.kind} at ${at}, ${o.widthM.toFixed(2)} x ${o.heightM.toFixed(2)} m, box ${JSON.stringify(o.image)}, partial [${o.partial.join(',')}], conf ${o.confidence.toFixed(2)}`;
}

function describeView(v: SolidView): string {
  const s = v.object.solid;
  const size =
    s.kind === 'box'
      ? `${(s.maxX - s.minX).toFixed(2)} x ${(s.maxY - s.minY).toFixed(2)}`
      : `r ${s.radius.toFixed(2)}`;
  return `${v.object.colour} ${v.object.kind} (${s.role}, ${size}, h ${s.height.toFixed(2)}) at ${v.distanceM.toFixed(2)} m, visible ${v.visible.toFixed(2)}, side margin ${v.sideMarginPx.toFixed(0)} px`;
}

/** What one case (knobs off or on) gathered over all worlds. */
class Tally {
  frames = 0;
  truth = 0;
  matched = 0;
  /** Misses by cause: the first that applies, in this order. */
  misses = { occluded: 0, sideEdge: 0, far: 0, smallOrOdd: 0, other: 0 };
  /** Of the truth, how many were partly hidden; of those, how many matched. */
  partlyHidden = 0;
  partlyHiddenMatched = 0;
  falsePositives = { phantom: 0, duplicate: 0, misplaced: 0 };
  /** Unmatched detections within 2 m of an object outside the truth set (far, cut, hidden). */
  outsideTruth = 0;
  /** Position errors of matched objects wholly in view and unoccluded, metres. */
  errors: number[] = [];
  errorsAll: number[] = [];
  byBand = new Map<string, number[]>();
  sideCutErrors: number[] = [];
  kindRight = 0;
  kindWrong = 0;
  kindUnknown = 0;
  cellsObserved = 0;
  cellsAgree = 0;
  cellsAgreeTolerant = 0;
  freeObserved = 0;
  freeAgree = 0;
  occupiedObserved = 0;
  occupiedAgree = 0;
  occupiedAgreeTolerant = 0;
  perceiveMs: number[] = [];
  /** How far the believed pose was from the true one: metres, and degrees of heading. */
  poseErrorM: number[] = [];
  headingErrorDeg: number[] = [];
}

function band(distanceM: number): string {
  return distanceM < 1 ? '0-1 m' : distanceM < 1.5 ? '1-1.5 m' : '1.5-2 m';
}

function isOddSize(view: SolidView): boolean {
  const s = view.object.solid;
  if (s.kind === 'box') {
    const w = s.maxX - s.minX;
    const d = s.maxY - s.minY;
    return Math.abs(w - 0.3) > 1e-6 || Math.abs(d - 0.3) > 1e-6 || Math.abs(s.height - 0.3) > 1e-6;
  }
  return Math.abs(s.radius - 0.15) > 1e-6 || Math.abs(s.height - 0.3) > 1e-6;
}

/** Matches the frame's detections to its truth and tallies the outcome. */
function scoreObjects(
  tally: Tally,
  objects: readonly SeenObject[],
  placed: ReadonlyArray<{ x: number; y: number }>,
  views: readonly SolidView[],
  where = '',
): void {
  const truth = views.filter((v) => v.distanceM <= TRUTH_RANGE_M && v.inView && v.visible > 0);
  tally.truth += truth.length;
  tally.partlyHidden += truth.filter((v) => v.visible < 1).length;
  // One-to-one, nearest pairs first, same colour within MATCH_M of the true centre.
  const pairs: Array<{ d: number; det: number; view: SolidView }> = [];
  objects.forEach((o, det) => {
    for (const view of truth) {
      if (view.object.colour !== o.colour) continue;
      const p = placed[det] ?? o.world;
      const d = Math.hypot(p.x - view.object.centre.x, p.y - view.object.centre.y);
      if (d <= MATCH_M) pairs.push({ d, det, view });
    }
  });
  pairs.sort((a, b) => a.d - b.d);
  const usedDet = new Set<number>();
  const usedView = new Set<SolidView>();
  for (const pair of pairs) {
    if (usedDet.has(pair.det) || usedView.has(pair.view)) continue;
    usedDet.add(pair.det);
    usedView.add(pair.view);
    const o = objects[pair.det];
    if (o === undefined) continue;
    tally.matched += 1;
    if (pair.view.visible < 1) tally.partlyHiddenMatched += 1;
    tally.errorsAll.push(pair.d);
    if (EXPLAIN && pair.d > 0.15) {
      console.log(
        `${where} error ${cm(pair.d)} cm: ${describe(o)}; truth ${describeView(pair.view)}`,
      );
    }
    if (pair.view.visible === 1) {
      tally.errors.push(pair.d);
      const key = band(pair.view.distanceM);
      tally.byBand.set(key, [...(tally.byBand.get(key) ?? []), pair.d]);
      if (o.partial.includes('side')) tally.sideCutErrors.push(pair.d);
    }
    if (o.kind === 'unknown') tally.kindUnknown += 1;
    else if (o.kind === pair.view.object.kind) tally.kindRight += 1;
    else tally.kindWrong += 1;
  }
  for (const view of truth) {
    if (usedView.has(view)) continue;
    if (EXPLAIN) console.log(`${where} miss: ${describeView(view)}`);
    if (view.visible < 1) tally.misses.occluded += 1;
    else if (view.sideMarginPx < 8) tally.misses.sideEdge += 1;
    else if (view.distanceM > 1.5) tally.misses.far += 1;
    else if (isOddSize(view)) tally.misses.smallOrOdd += 1;
    else tally.misses.other += 1;
  }
  objects.forEach((o, det) => {
    if (usedDet.has(det) || o.distanceM > TRUTH_RANGE_M) return;
    const p = placed[det] ?? o.world;
    const near = views.filter(
      (v) => v.object.colour === o.colour && distanceToSolid(p.x, p.y, v.object.solid) <= MATCH_M,
    );
    if (EXPLAIN && (near.length === 0 || near.some((v) => truth.includes(v)))) {
      const nearest = [...views].sort(
        (a, b) =>
          distanceToSolid(p.x, p.y, a.object.solid) - distanceToSolid(p.x, p.y, b.object.solid),
      )[0];
      const off =
        nearest === undefined ? '' : ` ${cm(distanceToSolid(p.x, p.y, nearest.object.solid))} cm`;
      console.log(
        `${where} false: ${describe(o)}; nearest coloured solid${off}: ${nearest === undefined ? 'none' : describeView(nearest)}`,
      );
    }
    if (near.length === 0) tally.falsePositives.phantom += 1;
    else if (near.some((v) => usedView.has(v))) tally.falsePositives.duplicate += 1;
    else if (near.some((v) => truth.includes(v))) tally.falsePositives.misplaced += 1;
    else tally.outsideTruth += 1;
  });
}

/** Compares the cells the grid observed with the true map, rasterised at cell centres. */
function scoreGrid(tally: Tally, grid: OccupancyGrid, world: World): void {
  const { width, height, resolutionM, originX, originY } = grid.spec;
  const solids = world.solids;
  for (let cy = 0; cy < height; cy += 1) {
    for (let cx = 0; cx < width; cx += 1) {
      const state = grid.stateOf(cx, cy);
      if (state === 'unknown') continue;
      const x = originX + (cx + 0.5) * resolutionM;
      const y = originY + (cy + 0.5) * resolutionM;
      const occupied = covered(x, y, solids);
      // Tolerant: a solid within one cell of the centre (a boundary cell either way).
      const near = covered(x, y, solids, resolutionM);
      tally.cellsObserved += 1;
      if (state === 'occupied') {
        tally.occupiedObserved += 1;
        if (occupied) tally.occupiedAgree += 1;
        if (near) tally.occupiedAgreeTolerant += 1;
        if (occupied) tally.cellsAgree += 1;
        if (near) tally.cellsAgreeTolerant += 1;
      } else {
        tally.freeObserved += 1;
        if (!occupied) tally.freeAgree += 1;
        if (!occupied) tally.cellsAgree += 1;
        if (!occupied || near) tally.cellsAgreeTolerant += 1;
      }
    }
  }
}

/**
 * Runs every scene's poses with the knobs off or on. `believed` places what is seen from the
 * pose the robot reports (what a robot has); `truePlaced` from where it truly is (perception's
 * own error, the odometry's taken out). With the knobs off the two are the same.
 */
async function runCase(
  scenes: readonly Scene[],
  withReality: boolean,
): Promise<{ believed: Tally; truePlaced: Tally }> {
  const believedTally = new Tally();
  const trueTally = new Tally();
  for (const scene of scenes) {
    const world = new World({ map: scene.map });
    const coloured = colouredSolids(world.solids);
    const perceiver = new FramePerceiver();
    const margin = 0.2;
    const grid = () =>
      new OccupancyGrid({
        widthM: scene.map.arena.width + 2 * margin,
        heightM: scene.map.arena.height + 2 * margin,
      });
    const believedGrid = grid();
    const trueGrid = grid();
    const random = new SeededRandom(scene.seed * 31 + 5);
    for (const [k, pose] of scene.poses.entries()) {
      const robot = placeRobot(
        world,
        pose,
        random,
        withReality ? { ...REALITY, seed: scene.seed * 10 + k + 1 } : undefined,
      );
      const truePose = { x: robot.x, y: robot.y, yaw: robot.yaw };
      const believed = robot.reportedPose;
      const jpeg = await encodeJpeg(renderRobotView(world, robot));
      const percept = await perceiver.perceive(jpeg, believed);
      world.removeRobot(robot.id);
      const views = coloured.map((c) => viewOf(c, truePose, projection, world.solids));
      for (const [tally, placed] of [
        [believedTally, percept.objects.map((o) => o.world)],
        [trueTally, percept.objects.map((o) => toWorld(truePose, o.robot))],
      ] as const) {
        tally.frames += 1;
        tally.perceiveMs.push(percept.timings.totalMs);
        tally.poseErrorM.push(Math.hypot(truePose.x - believed.x, truePose.y - believed.y));
        const dyaw = Math.atan2(
          Math.sin(truePose.yaw - believed.yaw),
          Math.cos(truePose.yaw - believed.yaw),
        );
        tally.headingErrorDeg.push(Math.abs((dyaw * 180) / Math.PI));
        const where = `${scene.mapName} seed ${scene.seed} pose ${k}${withReality ? ' knobs on' : ''}${tally === trueTally ? ' true-placed' : ''}`;
        scoreObjects(tally, percept.objects, placed, views, where);
      }
      integrateFreeSpace(believedGrid, believed, percept.freeSpace);
      integrateFreeSpace(trueGrid, truePose, percept.freeSpace);
    }
    scoreGrid(believedTally, believedGrid, world);
    scoreGrid(trueTally, trueGrid, world);
  }
  return { believed: believedTally, truePlaced: trueTally };
}

const started = performance.now();
const scenes = Array.from({ length: WORLDS }, (_, i) => makeScene(i + 1, POSES));
const off = await runCase(scenes, false);
const on = await runCase(scenes, true);
const cases = [
  { name: 'knobs off (believed pose = true pose)', key: 'off', tally: off.believed },
  { name: 'knobs on, placed from the odometry pose', key: 'on', tally: on.believed },
  {
    name: 'knobs on, placed from the true pose (perception alone)',
    key: 'on, true pose',
    tally: on.truePlaced,
  },
];
const seconds = (performance.now() - started) / 1000;

console.log(
  `perception accuracy: ${WORLDS} worlds (empty, room, obstacles maps in turn; 3..6 objects ` +
    `each), ${POSES} poses each, frames rendered 320x240 and JPEG-encoded; ${seconds.toFixed(0)} s`,
);
console.log(
  'truth: coloured solids (true colour named by colourOf, map furniture included) whose centre is ' +
    `within ${TRUTH_RANGE_M} m, whose footprint projects wholly inside the image, not wholly hidden`,
);
for (const { name, key, tally } of cases) {
  const t = tally;
  const fp = t.falsePositives.phantom + t.falsePositives.duplicate + t.falsePositives.misplaced;
  const recall = pct(t.matched, t.truth);
  const precision = pct(t.matched, t.matched + fp);
  const median = percentile(t.errors, 50);
  const p95 = percentile(t.errors, 95);
  const kinds = t.kindRight + t.kindWrong + t.kindUnknown;
  const kindAcc = pct(t.kindRight, kinds);
  const agreement = pct(t.cellsAgree, t.cellsObserved);
  const agreementTolerant = pct(t.cellsAgreeTolerant, t.cellsObserved);
  console.log(
    `\n${name} (${t.frames} frames; believed pose off the truth by median ` +
      `${cm(percentile(t.poseErrorM, 50))} cm / ${percentile(t.headingErrorDeg, 50).toFixed(1)} deg, ` +
      `p95 ${cm(percentile(t.poseErrorM, 95))} cm / ${percentile(t.headingErrorDeg, 95).toFixed(1)} deg):`,
  );
  console.log(
    `  objects: recall ${recall.toFixed(1)} % (${t.matched}/${t.truth}), precision ` +
      `${precision.toFixed(1)} % (${fp} false: ${t.falsePositives.phantom} phantom, ` +
      `${t.falsePositives.duplicate} duplicate, ${t.falsePositives.misplaced} > ${MATCH_M} m off); ` +
      `${t.outsideTruth} detections within 2 m of objects outside the truth set (not counted)`,
  );
  console.log(
    `  misses: ${t.misses.occluded} partly hidden, ${t.misses.sideEdge} within 8 px of a side, ` +
      `${t.misses.far} beyond 1.5 m, ${t.misses.smallOrOdd} of a non-default size, ` +
      `${t.misses.other} other; partly hidden objects matched ${t.partlyHiddenMatched}/${t.partlyHidden}`,
  );
  console.log(
    `  world position error (matched, wholly in view, unoccluded, n=${t.errors.length}): median ` +
      `${cm(median)} cm, p95 ${cm(p95)} cm; all matched (n=${t.errorsAll.length}): median ` +
      `${cm(percentile(t.errorsAll, 50))} cm, p95 ${cm(percentile(t.errorsAll, 95))} cm`,
  );
  for (const key2 of ['0-1 m', '1-1.5 m', '1.5-2 m']) {
    const xs = t.byBand.get(key2) ?? [];
    console.log(
      `    ${key2.padEnd(8)} n=${String(xs.length).padStart(4)}: median ${cm(percentile(xs, 50))} cm, ` +
        `p95 ${cm(percentile(xs, 95))} cm`,
    );
  }
  if (t.sideCutErrors.length > 0) {
    console.log(
      `    marked side-cut n=${t.sideCutErrors.length}: median ${cm(percentile(t.sideCutErrors, 50))} cm, ` +
        `p95 ${cm(percentile(t.sideCutErrors, 95))} cm`,
    );
  }
  console.log(
    `  kind: ${kindAcc.toFixed(1)} % right (${t.kindRight}/${kinds}; ${t.kindWrong} wrong, ` +
      `${t.kindUnknown} unknown)`,
  );
  console.log(
    `  free space: ${agreement.toFixed(1)} % of ${t.cellsObserved} observed cells agree with the ` +
      `true map (cell centres); ${agreementTolerant.toFixed(1)} % allowing one cell at a boundary; ` +
      `free cells ${pct(t.freeAgree, t.freeObserved).toFixed(1)} % right (${t.freeObserved}), ` +
      `occupied cells ${pct(t.occupiedAgree, t.occupiedObserved).toFixed(1)} % right ` +
      `(${pct(t.occupiedAgreeTolerant, t.occupiedObserved).toFixed(1)} % within one cell; ` +
      `${t.occupiedObserved})`,
  );
  console.log(
    `  perceive (decode + detect + free space) per frame: p50 ${percentile(t.perceiveMs, 50).toFixed(2)} ms`,
  );
  const note = `${t.frames} frames, ${t.truth} true objects; reality knobs ${key}`;
  reportFigure({
    bench: 'perception-accuracy',
    name: `object recall, knobs ${key}`,
    value: recall,
    unit: '%',
    better: 'higher',
    goal: '>= 95 %',
    met: recall >= 95,
    note,
  });
  reportFigure({
    bench: 'perception-accuracy',
    name: `object precision, knobs ${key}`,
    value: precision,
    unit: '%',
    better: 'higher',
    goal: '>= 95 %',
    met: precision >= 95,
    note,
  });
  reportFigure({
    bench: 'perception-accuracy',
    name: `object world position error median, knobs ${key}`,
    value: 100 * median,
    unit: 'cm',
    better: 'lower',
    goal: '<= 5 cm',
    met: median <= 0.05,
    note: `${t.errors.length} matched objects wholly in view and unoccluded`,
  });
  reportFigure({
    bench: 'perception-accuracy',
    name: `object world position error p95, knobs ${key}`,
    value: 100 * p95,
    unit: 'cm',
    better: 'lower',
    goal: '<= 15 cm',
    met: p95 <= 0.15,
    note: `${t.errors.length} matched objects wholly in view and unoccluded`,
  });
  reportFigure({
    bench: 'perception-accuracy',
    name: `object kind right, knobs ${key}`,
    value: kindAcc,
    unit: '%',
    better: 'higher',
    note: `${kinds} matched objects; unknown counts as wrong`,
  });
  reportFigure({
    bench: 'perception-accuracy',
    name: `free space cells agreeing with the map, knobs ${key}`,
    value: agreement,
    unit: '%',
    better: 'higher',
    goal: '>= 90 %',
    met: agreement >= 90,
    note: `${t.cellsObserved} observed cells; a cell is truly occupied when a solid covers its centre`,
  });
}
