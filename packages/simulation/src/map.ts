import { HalError } from '@hal/types';
import { z } from 'zod';

/*
 * The map format: a small JSON document describing an arena (a rectangle centred on the world
 * origin, walled all round), axis-aligned walls and box or cylinder obstacles, and where robots
 * start. World frame REP-103: x forward (east on the map), y left (north), z up; metres, radians.
 */

const metres = (what: string) => z.number().describe(`${what}, metres`);
const colour = z
  .string()
  .regex(/^#[0-9a-fA-F]{6}$/, 'colours are written "#rrggbb"')
  .describe('Colour, "#rrggbb"');

export const StartPoseSchema = z
  .object({
    x: metres('x').default(0),
    y: metres('y').default(0),
    yaw: z.number().default(0).describe('Heading, radians, counter-clockwise from +x'),
  })
  .describe('Where a robot starts');
export type StartPose = z.output<typeof StartPoseSchema>;

export const WallSchema = z
  .object({
    from: z.tuple([z.number(), z.number()]).describe('One end [x, y], metres'),
    to: z.tuple([z.number(), z.number()]).describe('The other end [x, y], metres'),
    thickness: z.number().gt(0).max(1).default(0.05).describe('Thickness, metres'),
    height: z.number().gt(0).max(3).default(0.3).describe('Height, metres'),
    color: colour.default('#8a94a6'),
  })
  .refine((w) => w.from[0] === w.to[0] || w.from[1] === w.to[1], {
    message: 'walls run along x or along y (from and to share an x or a y)',
  })
  .describe('A straight, axis-aligned wall');

export const BoxObstacleSchema = z
  .object({
    kind: z.literal('box'),
    x: metres('centre x'),
    y: metres('centre y'),
    width: z.number().gt(0).describe('Size along x, metres'),
    depth: z.number().gt(0).describe('Size along y, metres'),
    height: z.number().gt(0).max(3).default(0.25).describe('Height, metres'),
    color: colour.default('#e07a5f'),
  })
  .describe('An axis-aligned box');

export const CylinderObstacleSchema = z
  .object({
    kind: z.literal('cylinder'),
    x: metres('centre x'),
    y: metres('centre y'),
    radius: z.number().gt(0).describe('Radius, metres'),
    height: z.number().gt(0).max(3).default(0.25).describe('Height, metres'),
    color: colour.default('#3d85c6'),
  })
  .describe('An upright cylinder');

export const ObstacleSchema = z.discriminatedUnion('kind', [
  BoxObstacleSchema,
  CylinderObstacleSchema,
]);

export const WorldMapSchema = z
  .object({
    name: z.string().min(1).max(60).describe('Short name, shown in menus'),
    description: z.string().max(300).default('').describe('One sentence for people'),
    arena: z
      .object({
        width: z.number().gt(0).max(100).default(5).describe('Size along x, metres'),
        height: z.number().gt(0).max(100).default(5).describe('Size along y, metres'),
        wallHeight: z.number().gt(0).max(3).default(0.3).describe('Boundary wall height, metres'),
      })
      .prefault({})
      .describe('The walled rectangle, centred on the origin'),
    walls: z.array(WallSchema).default([]),
    obstacles: z.array(ObstacleSchema).default([]),
    starts: z
      .array(StartPoseSchema)
      .min(1)
      .default([{ x: 0, y: 0, yaw: 0 }])
      .describe('Start poses; robot i starts at starts[i % starts.length]'),
  })
  .describe('A simulation map');

/** A map as written (defaults may be left out). */
export type WorldMapInput = z.input<typeof WorldMapSchema>;
/** A map with every default filled in. */
export type WorldMap = z.output<typeof WorldMapSchema>;

/** Parses and checks a map (e.g. `parseMap(JSON.parse(text))`); throws INVALID_PARAMETER. */
export function parseMap(input: unknown): WorldMap {
  const parsed = WorldMapSchema.safeParse(input);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    const where = issue?.path.map(String).join('.') || 'map';
    throw new HalError('INVALID_PARAMETER', `map: "${where}" ${issue?.message ?? 'is invalid'}`, {
      details: { parameter: where },
    });
  }
  return parsed.data;
}
