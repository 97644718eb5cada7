import type { WorldMap } from './map.js';

/*
 * The solid geometry of a world, in plan view (metres): axis-aligned boxes and upright cylinders,
 * each with a height and a colour. Collision tests and ray casts are closed-form and allocate
 * nothing on their hot paths.
 */

/** An RGB colour, 0..255 each. */
export interface Rgb {
  r: number;
  g: number;
  b: number;
}

/** An axis-aligned box. */
export interface BoxSolid {
  kind: 'box';
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  height: number;
  color: Rgb;
  /** What it is, for reports: 'arena', 'wall', 'obstacle' or 'robot'. */
  role: SolidRole;
  /** Index within its role (the map's wall or obstacle index), for reports. */
  index: number;
}

/** An upright cylinder. */
export interface CylinderSolid {
  kind: 'cylinder';
  x: number;
  y: number;
  radius: number;
  height: number;
  color: Rgb;
  role: SolidRole;
  index: number;
}

export type SolidRole = 'arena' | 'wall' | 'obstacle' | 'robot';
export type Solid = BoxSolid | CylinderSolid;

/** Parses "#rrggbb". */
export function parseColor(text: string): Rgb {
  const value = Number.parseInt(text.slice(1), 16);
  return { r: (value >> 16) & 255, g: (value >> 8) & 255, b: value & 255 };
}

const ARENA_WALL_THICKNESS = 0.1;

/** The solids of a map: the four arena walls, then its walls, then its obstacles. */
export function solidsOf(map: WorldMap): Solid[] {
  const hw = map.arena.width / 2;
  const hh = map.arena.height / 2;
  const t = ARENA_WALL_THICKNESS;
  const h = map.arena.wallHeight;
  const arenaColor = parseColor('#5c6b80');
  const box = (
    minX: number,
    minY: number,
    maxX: number,
    maxY: number,
    height: number,
    color: Rgb,
    role: SolidRole,
    index: number,
  ): BoxSolid => ({ kind: 'box', minX, minY, maxX, maxY, height, color, role, index });
  const solids: Solid[] = [
    box(-hw - t, -hh - t, hw + t, -hh, h, arenaColor, 'arena', 0),
    box(-hw - t, hh, hw + t, hh + t, h, arenaColor, 'arena', 1),
    box(-hw - t, -hh, -hw, hh, h, arenaColor, 'arena', 2),
    box(hw, -hh, hw + t, hh, h, arenaColor, 'arena', 3),
  ];
  map.walls.forEach((wall, index) => {
    const half = wall.thickness / 2;
    const [x0, y0] = wall.from;
    const [x1, y1] = wall.to;
    solids.push(
      box(
        Math.min(x0, x1) - half,
        Math.min(y0, y1) - half,
        Math.max(x0, x1) + half,
        Math.max(y0, y1) + half,
        wall.height,
        parseColor(wall.color),
        'wall',
        index,
      ),
    );
  });
  map.obstacles.forEach((o, index) => {
    if (o.kind === 'box') {
      solids.push(
        box(
          o.x - o.width / 2,
          o.y - o.depth / 2,
          o.x + o.width / 2,
          o.y + o.depth / 2,
          o.height,
          parseColor(o.color),
          'obstacle',
          index,
        ),
      );
    } else {
      solids.push({
        kind: 'cylinder',
        x: o.x,
        y: o.y,
        radius: o.radius,
        height: o.height,
        color: parseColor(o.color),
        role: 'obstacle',
        index,
      });
    }
  });
  return solids;
}

/** A point in the plane, metres. */
export interface Point {
  x: number;
  y: number;
}

/**
 * The point of `solid` nearest to the centre of a disc of radius `r` at (x, y) when the disc
 * overlaps the solid, else undefined.
 */
export function discContact(x: number, y: number, r: number, solid: Solid): Point | undefined {
  if (solid.kind === 'box') {
    const cx = x < solid.minX ? solid.minX : x > solid.maxX ? solid.maxX : x;
    const cy = y < solid.minY ? solid.minY : y > solid.maxY ? solid.maxY : y;
    const dx = x - cx;
    const dy = y - cy;
    return dx * dx + dy * dy < r * r ? { x: cx, y: cy } : undefined;
  }
  const dx = x - solid.x;
  const dy = y - solid.y;
  const reach = r + solid.radius;
  const d2 = dx * dx + dy * dy;
  if (d2 >= reach * reach) return undefined;
  const d = Math.sqrt(d2);
  if (d === 0) return { x: solid.x, y: solid.y };
  return { x: solid.x + (dx / d) * solid.radius, y: solid.y + (dy / d) * solid.radius };
}

/** Distance from (x, y) to the nearest point of `solid`, metres (0 inside it). */
export function pointDistance(x: number, y: number, solid: Solid): number {
  if (solid.kind === 'box') {
    const dx = x < solid.minX ? solid.minX - x : x > solid.maxX ? x - solid.maxX : 0;
    const dy = y < solid.minY ? solid.minY - y : y > solid.maxY ? y - solid.maxY : 0;
    return Math.sqrt(dx * dx + dy * dy);
  }
  return Math.max(0, Math.hypot(x - solid.x, y - solid.y) - solid.radius);
}

/**
 * Distance along the ray (ox, oy) + t (dx, dy) (a unit direction) at which it enters `solid`,
 * or Infinity when it misses. A ray starting inside a solid hits it at 0.
 */
export function rayEnter(ox: number, oy: number, dx: number, dy: number, solid: Solid): number {
  if (solid.kind === 'box') {
    let tmin = -Infinity;
    let tmax = Infinity;
    if (dx !== 0) {
      const t1 = (solid.minX - ox) / dx;
      const t2 = (solid.maxX - ox) / dx;
      tmin = Math.max(tmin, Math.min(t1, t2));
      tmax = Math.min(tmax, Math.max(t1, t2));
    } else if (ox < solid.minX || ox > solid.maxX) {
      return Infinity;
    }
    if (dy !== 0) {
      const t1 = (solid.minY - oy) / dy;
      const t2 = (solid.maxY - oy) / dy;
      tmin = Math.max(tmin, Math.min(t1, t2));
      tmax = Math.min(tmax, Math.max(t1, t2));
    } else if (oy < solid.minY || oy > solid.maxY) {
      return Infinity;
    }
    if (tmax < 0 || tmin > tmax) return Infinity;
    return tmin < 0 ? 0 : tmin;
  }
  const fx = ox - solid.x;
  const fy = oy - solid.y;
  const b = fx * dx + fy * dy;
  const c = fx * fx + fy * fy - solid.radius * solid.radius;
  if (c <= 0) return 0;
  const disc = b * b - c;
  if (disc < 0 || b > 0) return Infinity;
  return -b - Math.sqrt(disc);
}

/**
 * Whether the ray enters a box through a face normal to x (true) or to y (false), for shading.
 * Only meaningful for a box the ray hits at `t`.
 */
export function hitsXFace(ox: number, dx: number, t: number, solid: BoxSolid): boolean {
  const x = ox + dx * t;
  return Math.abs(x - solid.minX) < 1e-6 || Math.abs(x - solid.maxX) < 1e-6;
}

/** The nearest solid along a ray within `maxRange`, and how far it is. */
export function castRay(
  ox: number,
  oy: number,
  angle: number,
  maxRange: number,
  solids: readonly Solid[],
  skip?: Solid,
): { distance: number; solid: Solid | undefined } {
  const dx = Math.cos(angle);
  const dy = Math.sin(angle);
  let best = maxRange;
  let hit: Solid | undefined;
  for (const solid of solids) {
    if (solid === skip) continue;
    const t = rayEnter(ox, oy, dx, dy, solid);
    if (t < best) {
      best = t;
      hit = solid;
    }
  }
  return { distance: best, solid: hit };
}
