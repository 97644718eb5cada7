/**
 * A known map to seed the world model with, in the simulation's map format (so a `WorldMap` from
 * `@hal/simulation` can be passed as it is): a walled arena rectangle centred on the origin,
 * axis-aligned walls, and box and cylinder obstacles. Metres, world frame (REP-103).
 */
export interface KnownMap {
  /** The walled rectangle, centred on the origin. */
  arena?: { width: number; height: number };
  /** Straight walls from one end to the other, `thickness` metres thick (default 0.05). */
  walls?: readonly {
    from: readonly [number, number];
    to: readonly [number, number];
    thickness?: number;
  }[];
  /** Boxes (centre, size along x and y) and upright cylinders (centre, radius). */
  obstacles?: readonly (
    | { kind: 'box'; x: number; y: number; width: number; depth: number }
    | { kind: 'cylinder'; x: number; y: number; radius: number }
  )[];
}

/** A solid of a known map, reduced to what the grid needs. */
export type MapSolid =
  | { kind: 'rect'; minX: number; minY: number; maxX: number; maxY: number }
  | { kind: 'circle'; x: number; y: number; radius: number };

/** The solids of a known map (walls and boxes as rectangles, cylinders as circles). */
export function mapSolids(map: KnownMap): MapSolid[] {
  const solids: MapSolid[] = [];
  for (const wall of map.walls ?? []) {
    const half = (wall.thickness ?? 0.05) / 2;
    solids.push({
      kind: 'rect',
      minX: Math.min(wall.from[0], wall.to[0]) - half,
      minY: Math.min(wall.from[1], wall.to[1]) - half,
      maxX: Math.max(wall.from[0], wall.to[0]) + half,
      maxY: Math.max(wall.from[1], wall.to[1]) + half,
    });
  }
  for (const o of map.obstacles ?? []) {
    if (o.kind === 'box') {
      solids.push({
        kind: 'rect',
        minX: o.x - o.width / 2,
        minY: o.y - o.depth / 2,
        maxX: o.x + o.width / 2,
        maxY: o.y + o.depth / 2,
      });
    } else {
      solids.push({ kind: 'circle', x: o.x, y: o.y, radius: o.radius });
    }
  }
  return solids;
}
