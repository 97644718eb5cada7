import { HalError } from '@hal/types';
import type { SimRobot } from '../robot/sim-robot.js';
import type { World } from '../world.js';

const round = (m: number): number => Math.floor(m * 1000) / 1000;

/**
 * Refuses a `moveTo` target that the robot's centre cannot reach inside the arena's walls (the
 * arena is centred on the origin; the walls' inner faces are at half its width and height, and
 * the footprint keeps the centre its radius away from them): RANGE_EXCEEDED naming the limits,
 * before anything moves. Obstacles inside the arena are the drive's business (COLLISION).
 */
export function checkInsideArena(world: World, robot: SimRobot, x: number, y: number): void {
  const { width, height } = world.map.arena;
  const maxX = round(width / 2 - robot.radius);
  const maxY = round(height / 2 - robot.radius);
  if (Math.abs(x) <= maxX && Math.abs(y) <= maxY) return;
  throw new HalError(
    'RANGE_EXCEEDED',
    `moveTo target (${x}, ${y}) m is outside the ${width} x ${height} m arena: the robot's centre ` +
      `can reach x within -${maxX}..${maxX} m and y within -${maxY}..${maxY} m ` +
      `(the walls less its footprint radius, ${robot.radius} m)`,
    {
      details: {
        parameter: Math.abs(x) > maxX ? 'x' : 'y',
        limits: { x: [-maxX, maxX], y: [-maxY, maxY] },
        arena: { width, height },
      },
    },
  );
}
