import type { Contact, FreeSpace } from './robot/contact.js';
import type { SimRobot } from './robot/sim-robot.js';
import { discContact, pointDistance } from './shapes.js';
import type { Solid } from './shapes.js';

/*
 * What a robot touches, and how much room it has, among a world's solids and robots. Other robots
 * are looked at first through where they were last integrated and how far they can have moved
 * since (`settledX/Y`, `maxSpeedMps`): only those that could matter are brought up to the clock.
 */

/** Longest a measurement of room is trusted, µs: robots re-measure at least this often while moving. */
export const ROOM_HORIZON_US = 5_000_000;

/** How far `robot` can be from where it was last integrated, at `nowUs`, metres. */
function drift(robot: SimRobot, nowUs: number): number {
  if (!robot.running) return 0;
  // The top speed over the time since, plus one step's worth for the step due at that instant.
  return robot.maxSpeedMps * (Math.max(0, nowUs - robot.settledUs) / 1e6) + robot.stepLengthM;
}

/**
 * What a disc at (x, y) of radius r touches (solids first, then robots), or undefined. Only the
 * robots in `candidates` (indices, ascending) are looked at, all when it is undefined.
 */
export function contactAmong(
  x: number,
  y: number,
  r: number,
  solids: readonly Solid[],
  robots: readonly SimRobot[],
  self: SimRobot | undefined,
  nowUs: number,
  candidates?: readonly number[],
): Contact | undefined {
  for (const solid of solids) {
    const point = discContact(x, y, r, solid);
    if (point !== undefined) return { point, role: solid.role, index: solid.index };
  }
  const count = candidates === undefined ? robots.length : candidates.length;
  for (let n = 0; n < count; n += 1) {
    const i = candidates === undefined ? n : (candidates[n] as number);
    const other = robots[i] as SimRobot;
    if (other === self) continue;
    const reach = r + other.radius;
    const far = reach + drift(other, nowUs);
    let dx = x - other.settledX;
    let dy = y - other.settledY;
    if (dx * dx + dy * dy >= far * far) continue;
    const ox = other.x;
    const oy = other.y;
    dx = x - ox;
    dy = y - oy;
    const d2 = dx * dx + dy * dy;
    if (d2 >= reach * reach) continue;
    const d = Math.sqrt(d2) || 1;
    return {
      point: { x: ox + (dx / d) * other.radius, y: oy + (dy / d) * other.radius },
      role: 'robot',
      index: i,
      robotId: other.id,
    };
  }
  return undefined;
}

/**
 * The room of `self`, a disc of radius r at (x, y) at `nowUs`: the distance to the nearest solid,
 * and until when (at most {@link ROOM_HORIZON_US} ahead) no other robot can touch it. Two robots a
 * gap g apart, with top speeds v1 and v2, cannot touch before g / (v1 + v2) has passed, whatever
 * commands they get meanwhile. Only the robots in `candidates` are looked at, all when it is
 * undefined: the caller leaves out only robots too far away to matter within the horizon.
 */
export function freeSpaceAmong(
  x: number,
  y: number,
  r: number,
  solids: readonly Solid[],
  robots: readonly SimRobot[],
  self: SimRobot,
  nowUs: number,
  candidates?: readonly number[],
): FreeSpace {
  let distance = Number.POSITIVE_INFINITY;
  for (const solid of solids) {
    const d = pointDistance(x, y, solid) - r;
    if (d < distance) distance = d;
  }
  let untilUs = nowUs + ROOM_HORIZON_US;
  const own = self.maxSpeedMps;
  const count = candidates === undefined ? robots.length : candidates.length;
  for (let n = 0; n < count; n += 1) {
    const other = robots[candidates === undefined ? n : (candidates[n] as number)] as SimRobot;
    if (other === self) continue;
    const speed = own + other.maxSpeedMps;
    if (speed <= 0) continue;
    const reach = r + other.radius;
    let gap = Math.hypot(x - other.settledX, y - other.settledY) - reach - drift(other, nowUs);
    if (nowUs + (gap / speed) * 1e6 >= untilUs) continue;
    gap = Math.hypot(x - other.x, y - other.y) - reach;
    const t = nowUs + Math.floor((Math.max(0, gap) / speed) * 1e6);
    if (t < untilUs) untilUs = t;
  }
  return { distance, untilUs };
}
