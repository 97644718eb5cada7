// A known map for the grid's unit tests: an arena with a wall, a box and a cylinder. Not exported.

/** A 4 m x 4 m arena with a wall, a box and a cylinder. */
export const boxMap = {
  arena: { width: 4, height: 4 },
  walls: [{ from: [0, -2] as [number, number], to: [0, -1] as [number, number], thickness: 0.1 }],
  obstacles: [
    { kind: 'box' as const, x: 1, y: 1, width: 0.4, depth: 0.2 },
    { kind: 'cylinder' as const, x: -1, y: 1, radius: 0.2 },
  ],
};
