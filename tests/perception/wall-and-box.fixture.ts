/**
 * A world for the emulated cube's camera tests, in the eval task format: the robot starts at the
 * origin facing +x, a yellow 0.3 m box stands ahead-left at (0.7, 0.25), a wall 1.2 m ahead.
 */
export const WALL_AND_BOX_WORLD = {
  map: {
    name: 'a wall ahead',
    arena: { width: 6, height: 6 },
    walls: [{ from: [1.2, -1.5], to: [1.2, 1.5], thickness: 0.06 }],
  },
  start: { x: 0, y: 0, yawDeg: 0 },
  objects: [{ name: 'target', kind: 'box', colour: 'yellow', x: 0.7, y: 0.25 }],
};
