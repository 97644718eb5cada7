import { WorldMapSchema } from '@hal/simulation';
import { z } from 'zod';
import { RealitySchema } from './reality.js';

/*
 * The task file format, version 1. A task is a family: a world, an instruction, budgets and the
 * checks that decide success from the simulator's ground truth; a seed picks one member (start
 * pose and object placement jittered within the task's `variants`). Metres, degrees where a name
 * says so, world frame REP-103 (x forward, y left, yaw counter-clockwise).
 */

/** The colours objects may have, by name, and how they are drawn. */
export const COLOURS = {
  red: '#d62828',
  green: '#2a9d3f',
  blue: '#1d4ed8',
  yellow: '#f4c430',
  purple: '#7b2cbf',
  orange: '#f77f00',
} as const;
export type ColourName = keyof typeof COLOURS;
const colourNames = Object.keys(COLOURS) as [ColourName, ...ColourName[]];

export const TASK_GROUPS = [
  'precision',
  'goals',
  'perception',
  'safety',
  'robustness',
  'search',
  'memory',
  'sequences',
] as const;
export type TaskGroup = (typeof TASK_GROUPS)[number];

const metres = (what: string) => z.number().finite().describe(`${what}, metres`);
const positive = (what: string) => z.number().finite().gt(0).describe(what);

export const ObjectSchema = z
  .object({
    name: z
      .string()
      .regex(/^[a-z][a-z0-9-]*$/, 'names are lower-case words joined by "-"')
      .describe('The name checks use, e.g. "red-box"'),
    kind: z.enum(['box', 'cylinder']),
    colour: z.enum(colourNames),
    x: metres('centre x'),
    y: metres('centre y'),
    width: positive('box size along x, metres').default(0.3),
    depth: positive('box size along y, metres').default(0.3),
    radius: positive('cylinder radius, metres').default(0.15),
    height: positive('height, metres').max(3).default(0.3),
  })
  .strict()
  .describe('A named, coloured object the robot can see and bump into');
export type TaskObject = z.output<typeof ObjectSchema>;

export const SensorsSchema = z
  .object({
    camera: z.boolean().default(true),
    rangeSensors: z.boolean().default(true),
    imu: z.boolean().default(true),
  })
  .strict()
  .describe('Which sensors the robot has');

/** The built-in maps a task may name. */
const MAP_NAMES = ['empty', 'room', 'obstacles', 'maze'] as const;

export const WorldSchema = z
  .object({
    map: z
      .union([z.enum(MAP_NAMES), WorldMapSchema], {
        // zod's own message for a union is "Invalid input": say what the choices are
        error: (issue) =>
          `Invalid option: expected one of ${MAP_NAMES.map((n) => `"${n}"`).join('|')} or a map written out (an object), got ${JSON.stringify(issue.input)}`,
      })
      .default('empty')
      .describe('A built-in map by name, or a map written out'),
    start: z
      .object({ x: metres('x'), y: metres('y'), yawDeg: z.number().finite().default(0) })
      .strict()
      .describe('The robot start pose; yaw in degrees'),
    objects: z.array(ObjectSchema).default([]),
    sensors: SensorsSchema.prefault({}),
  })
  .strict();

export const VariantsSchema = z
  .object({
    startM: z.number().min(0).max(1).default(0).describe('Start x and y jitter, ± metres'),
    yawDeg: z.number().min(0).max(180).default(0).describe('Start heading jitter, ± degrees'),
    objectsM: z.number().min(0).max(1).default(0).describe('Object placement jitter, ± metres'),
    colours: z.boolean().default(false).describe("A seed draws each object's colour from the six"),
    maybeObjects: z
      .array(z.string())
      .default([])
      .describe('Objects (by name) a seed keeps or leaves out, at even odds each'),
    mirror: z
      .boolean()
      .default(false)
      .describe(
        'At even odds a seed mirrors the start and the objects across y = 0 (left becomes right); for maps symmetric about y = 0',
      ),
  })
  .strict()
  .describe('How far a seed moves the start and the objects, and what else it draws');

export const BudgetSchema = z
  .object({
    toolCalls: z.number().int().min(1).max(1000).default(30).describe('Most tool calls'),
    simSeconds: z.number().gt(0).max(3600).default(300).describe('Most simulated time, seconds'),
  })
  .strict();

export const LeashSchema = z
  .object({
    maxDistanceM: positive('longest path of one motion call, metres').optional(),
    geofence: z
      .object({ minX: z.number(), maxX: z.number(), minY: z.number(), maxY: z.number() })
      .strict()
      .refine((f) => f.minX < f.maxX && f.minY < f.maxY, 'min must be below max')
      .optional(),
  })
  .strict()
  .describe('The leash the tools run under (see @hal/tools)');

/** The fault target that means any motion tool: the nth motion call that asks to move. */
export const ANY_MOTION = 'motion';
const toolName = z
  .string()
  .regex(/^[a-z_]+$/, 'a tool name, e.g. "move_forward"')
  .describe(
    `A tool's name, or "${ANY_MOTION}": the nth call of any motion tool that asks to move (1 cm or 1° or more)`,
  );
export const FaultSchema = z
  .discriminatedUnion('kind', [
    z
      .object({
        kind: z.literal('fail'),
        tool: toolName,
        nth: z.number().int().min(1).default(1).describe('Which call of that tool fails'),
        code: z.string().default('HARDWARE_ERROR'),
      })
      .strict()
      .describe('The nth call of a tool fails without running'),
    z
      .object({
        kind: z.literal('timeout'),
        tool: toolName,
        nth: z.number().int().min(1).default(1),
      })
      .strict()
      .describe('The nth call of a tool answers TIMEOUT without running'),
    z
      .object({
        kind: z.literal('estop'),
        afterMotions: z.number().int().min(1).default(1).describe('After this many motion calls'),
      })
      .strict()
      .describe('An operator engages the emergency stop during the task'),
  ])
  .describe('Something that goes wrong on purpose');
export type Fault = z.output<typeof FaultSchema>;

/** The questions an answer check may ask. */
export const QUESTIONS = [
  'colour-ahead',
  'count-boxes',
  'open-side',
  'colour-of',
  'count-pillars',
] as const;
export type Question = (typeof QUESTIONS)[number];

export const AreaSchema = z
  .object({ minX: z.number(), maxX: z.number(), minY: z.number(), maxY: z.number() })
  .strict()
  .refine((a) => a.minX < a.maxX && a.minY < a.maxY, 'min must be below max')
  .describe('A rectangle of the world, metres');
export type Area = z.output<typeof AreaSchema>;

export const StopSchema = z
  .union([
    z
      .object({
        object: z.string().describe('The name of an object of the world'),
        withinM: positive('most distance from the robot centre to its surface, metres'),
      })
      .strict(),
    z
      .object({
        x: metres('x'),
        y: metres('y'),
        withinM: positive('most distance from the robot centre to the point, metres'),
      })
      .strict(),
  ])
  .describe('A place to visit: near an object, or at a point');
export type Stop = z.output<typeof StopSchema>;

export const CheckSchema = z
  .discriminatedUnion('kind', [
    z
      .object({
        kind: z.literal('displacement'),
        forwardM: metres('forward of the start pose').default(0),
        leftM: metres('left of the start pose').default(0),
        toleranceM: positive('allowed position error, metres'),
        headingDeg: z
          .number()
          .finite()
          .optional()
          .describe('Heading change from the start, degrees'),
        headingToleranceDeg: positive('allowed heading error, degrees').default(3),
      })
      .strict()
      .describe('End at a pose relative to the start'),
    z
      .object({
        kind: z.literal('return'),
        minExcursionM: positive('how far the robot must have gone, metres'),
        toleranceM: positive('allowed distance from the start at the end, metres'),
      })
      .strict()
      .describe('Go somewhere and come back to the start'),
    z
      .object({
        kind: z.literal('reach-object'),
        object: z.string().describe('The name of an object of the world'),
        withinM: positive('most distance from the robot centre to its surface, metres'),
      })
      .strict(),
    z
      .object({
        kind: z.literal('reach-point'),
        x: metres('x'),
        y: metres('y'),
        toleranceM: positive('metres'),
      })
      .strict(),
    z
      .object({
        kind: z.literal('answer'),
        question: z.enum(QUESTIONS),
        object: z
          .string()
          .optional()
          .describe('For "colour-of": the name of the object whose colour is asked'),
        area: AreaSchema.optional().describe(
          'For "count-boxes" and "count-pillars": count only the objects whose centre lies here',
        ),
      })
      .strict()
      .describe(
        "The final answer holds the world's true answer (computed at the start pose, in the world the seed drew)",
      ),
    z
      .object({
        kind: z.literal('visit-in-order'),
        stops: z.array(StopSchema).min(1).describe('The places to visit, in this order'),
        returnM: positive('most distance from the start at the end, metres')
          .optional()
          .describe('Then end back at the start, within this many metres'),
      })
      .strict()
      .describe(
        "Stop at each place in turn (a position the trial logs after a call, within the stop's reach), in order; maybe then back to the start",
      ),
    z
      .object({
        kind: z.literal('stop-before'),
        maxGapM: positive('most gap left between the body and what is ahead, metres'),
        minTravelM: positive('least distance driven, metres').default(0.2),
      })
      .strict()
      .describe('Drive toward something and stop before it, without touching'),
    z
      .object({
        kind: z.literal('fence-respected'),
        x: metres('x of the point the instruction names (outside the fence)'),
        y: metres('y of that point'),
        approachM: positive('most distance from that point brought into the fence, metres'),
      })
      .strict()
      .describe("Stay inside the leash's geofence, ending near the fence's point nearest the goal"),
    z
      .object({
        kind: z.literal('estop'),
        latched: z.boolean().describe('Whether the stop must still be latched at the end'),
        reported: z.boolean().default(false).describe('The answer must mention the stop'),
      })
      .strict(),
    z
      .object({ kind: z.literal('no-collision') })
      .strict()
      .describe('Never touch anything (every task fails on a collision unless it allows them)'),
  ])
  .describe('One condition of success, computed from ground truth');
export type Check = z.output<typeof CheckSchema>;

export const TaskSchema = z
  .object({
    id: z.string().regex(/^[a-z0-9-]+\/[a-z0-9-]+$/, 'ids are "group/name"'),
    group: z.enum(TASK_GROUPS),
    instruction: z.string().min(1).max(1000).describe('What the agent is told, in words'),
    world: WorldSchema,
    variants: VariantsSchema.prefault({}),
    budget: BudgetSchema.prefault({}),
    leash: LeashSchema.optional(),
    faults: z.array(FaultSchema).default([]),
    reality: RealitySchema.optional().describe(
      "Reality knobs this task runs with at the least (a harder variant): each knob is the higher of the task's and the run's",
    ),
    allowCollisions: z.boolean().default(false),
    checks: z.array(CheckSchema).min(1).describe('All must hold for success'),
  })
  .strict();
export type Task = z.output<typeof TaskSchema>;
export type TaskInput = z.input<typeof TaskSchema>;

export const TASK_FILE_VERSION = 1;

export const TaskFileSchema = z
  .object({
    version: z.literal(TASK_FILE_VERSION).describe('The task file format version'),
    tasks: z.array(TaskSchema).min(1),
  })
  .strict();
export type TaskFile = z.output<typeof TaskFileSchema>;
