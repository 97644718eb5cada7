// Seeded scenes for the perception benchmarks: a built-in map with task-like coloured objects
// added (the eval's six colours; boxes 0.3 x 0.3 x 0.3 and pillars r 0.15 h 0.3 mostly, some of
// other sizes), and robot poses that are not inside anything, most of them looking roughly at
// one of the objects from 0.35..2.1 m, the rest anywhere.
import { COLOURS } from '@hal/eval';
import { BUILTIN_MAPS, SeededRandom, World } from '@hal/simulation';
import type { BodyErrorInput, SimRobot, Solid, WorldMap } from '@hal/simulation';
import { distanceToSolid } from './perception-truth.js';
import type { PlanePose } from './perception-truth.js';

export const SCENE_MAPS = ['empty', 'room', 'obstacles'] as const;
export type SceneMapName = (typeof SCENE_MAPS)[number];

type Obstacle = WorldMap['obstacles'][number];

/** One seeded scene: its map (with the objects added) and the poses to look from. */
export interface Scene {
  seed: number;
  mapName: SceneMapName;
  map: WorldMap;
  poses: PlanePose[];
}

const ROBOT_CLEARANCE_M = 0.1; // radius 0.07 and a little

function footprintRadius(o: Obstacle): number {
  return o.kind === 'box' ? Math.hypot(o.width, o.depth) / 2 : o.radius;
}

/** An object of the task's kind: mostly the default sizes, one in five another size. */
function drawObject(random: SeededRandom, x: number, y: number): Obstacle {
  const names = Object.keys(COLOURS) as Array<keyof typeof COLOURS>;
  const color = COLOURS[names[Math.floor(random.next() * names.length)] ?? 'red'];
  const odd = random.next() < 0.2;
  const between = (a: number, b: number) => a + (b - a) * random.next();
  if (random.next() < 0.5) {
    const width = odd ? between(0.15, 0.5) : 0.3;
    const depth = odd ? between(0.15, 0.5) : 0.3;
    const height = odd ? between(0.15, 0.5) : 0.3;
    return { kind: 'box', x, y, width, depth, height, color };
  }
  const radius = odd ? between(0.06, 0.25) : 0.15;
  const height = odd ? between(0.15, 0.5) : 0.3;
  return { kind: 'cylinder', x, y, radius, height, color };
}

/** Whether a disc at (x, y) of radius r keeps `gap` from every solid and inside the arena. */
function clearOf(solids: readonly Solid[], x: number, y: number, r: number, gap: number): boolean {
  return solids.every((s) => distanceToSolid(x, y, s) > r + gap);
}

/** The scene of `seed`: its map in turn, 3..6 objects, `poseCount` poses. */
export function makeScene(seed: number, poseCount: number): Scene {
  const random = new SeededRandom(seed * 7919 + 17);
  const mapName = SCENE_MAPS[seed % SCENE_MAPS.length] ?? 'empty';
  const base = BUILTIN_MAPS[mapName];
  const halfW = base.arena.width / 2;
  const halfH = base.arena.height / 2;
  const objects: Obstacle[] = [];
  const count = 3 + Math.floor(random.next() * 4);
  let solids = new World({ map: base }).solids;
  for (let tries = 0; objects.length < count && tries < 200; tries += 1) {
    const x = (random.next() * 2 - 1) * (halfW - 0.4);
    const y = (random.next() * 2 - 1) * (halfH - 0.4);
    const object = drawObject(random, x, y);
    if (!clearOf(solids, x, y, footprintRadius(object), 0.2)) continue;
    objects.push(object);
    solids = new World({ map: { ...base, obstacles: [...base.obstacles, ...objects] } }).solids;
  }
  const map: WorldMap = { ...base, obstacles: [...base.obstacles, ...objects] };
  const poses: PlanePose[] = [];
  for (let k = 0; k < poseCount; k += 1) {
    const aimed = k < Math.ceil((poseCount * 3) / 5) && objects.length > 0;
    for (let tries = 0; tries < 100; tries += 1) {
      let pose: PlanePose;
      if (aimed) {
        const target = objects[Math.floor(random.next() * objects.length)] ?? objects[0];
        if (target === undefined) break;
        const r = 0.35 + random.next() * 1.75;
        const phi = random.next() * 2 * Math.PI;
        pose = {
          x: target.x + r * Math.cos(phi),
          y: target.y + r * Math.sin(phi),
          yaw: phi + Math.PI + (random.next() * 2 - 1) * 0.45,
        };
      } else {
        pose = {
          x: (random.next() * 2 - 1) * (halfW - ROBOT_CLEARANCE_M),
          y: (random.next() * 2 - 1) * (halfH - ROBOT_CLEARANCE_M),
          yaw: random.next() * 2 * Math.PI,
        };
      }
      if (Math.abs(pose.x) > halfW - ROBOT_CLEARANCE_M) continue;
      if (Math.abs(pose.y) > halfH - ROBOT_CLEARANCE_M) continue;
      if (!clearOf(solids, pose.x, pose.y, ROBOT_CLEARANCE_M, 0.01)) continue;
      poses.push(pose);
      break;
    }
  }
  return { seed, mapName, map, poses };
}

/**
 * Puts a robot at `pose` the way a robot gets anywhere: it starts up to 0.9 m back along a line
 * up to 60 degrees off its final heading, drives forward to `pose` and turns onto its heading,
 * with `bodyError` (when given) making its true motion and its odometry differ. Without a body
 * error the robot ends at `pose` and believes it. Where no clear run-up is found, it starts at
 * `pose`.
 */
export function placeRobot(
  world: World,
  pose: PlanePose,
  random: SeededRandom,
  bodyError?: BodyErrorInput,
): SimRobot {
  const solids = world.solids;
  let start: PlanePose = pose;
  let run = 0;
  let turn = 0;
  for (let tries = 0; tries < 20; tries += 1) {
    const d = 0.4 + random.next() * 0.5;
    const delta = (random.next() * 2 - 1) * (Math.PI / 3);
    const heading = pose.yaw - delta;
    const sx = pose.x - d * Math.cos(heading);
    const sy = pose.y - d * Math.sin(heading);
    let clear = true;
    for (let f = 0; f <= 1 && clear; f += 0.05) {
      const x = sx + f * (pose.x - sx);
      const y = sy + f * (pose.y - sy);
      const halfW = world.map.arena.width / 2;
      const halfH = world.map.arena.height / 2;
      clear =
        Math.abs(x) < halfW - ROBOT_CLEARANCE_M &&
        Math.abs(y) < halfH - ROBOT_CLEARANCE_M &&
        clearOf(solids, x, y, ROBOT_CLEARANCE_M, 0.01);
    }
    if (!clear) continue;
    start = { x: sx, y: sy, yaw: heading };
    run = d;
    turn = delta;
    break;
  }
  const robot = world.addRobot({
    start,
    ...(bodyError === undefined ? {} : { bodyError }),
  });
  if (run > 0) {
    robot.moveCm(run * 100, run * 100);
    world.advanceUntil(() => !robot.running, 60_000_000);
    robot.rotateDeg((turn * 180) / Math.PI);
    world.advanceUntil(() => !robot.running, 60_000_000);
  }
  return robot;
}
