import type { AgentTool, JsonSchemaObject } from '@hal/tools';
import { z } from 'zod';

/** Words naming a thing: a colour and a kind ("red box"), as `find`, `go_to`... take them. */
const Target = z.string().trim().min(1).max(60);
const Metres = z.number().finite().min(-50).max(50);

/** The skills' parameters, checked before anything moves (unknown keys are refused). */
export const SKILL_PARAMETERS = {
  look: z.object({ around: z.boolean().optional() }).strict(),
  find: z.object({ target: Target }).strict(),
  go_to: z.object({ target: Target }).strict(),
  go_to_point: z.object({ x: Metres, y: Metres }).strict(),
  face: z.object({ target: Target }).strict(),
  explore: z.object({}).strict(),
  where_is: z.object({ target: Target }).strict(),
  what_have_you_seen: z.object({}).strict(),
  go_back: z.object({}).strict(),
  move: z.object({ cm: z.number().finite().min(-500).max(500) }).strict(),
  turn: z.object({ degrees: z.number().finite().min(-360).max(360) }).strict(),
} as const;

/** A skill's name. */
export type SkillName = keyof typeof SKILL_PARAMETERS;

/** Every skill, in the order they are offered. */
export const SKILL_NAMES = Object.keys(SKILL_PARAMETERS) as SkillName[];

const COLOURS = ['red', 'orange', 'yellow', 'green', 'blue', 'purple'] as const;
/**
 * A thing's name as the JSON Schema offers it: a colour and a kind, or a colour alone. An enum,
 * so a model (and a small model's grammar) names only what perception can find; the skills also
 * read looser words ("the red one") when a client sends them.
 */
const target = {
  type: 'string',
  description: 'what to look for: a colour and a kind',
  enum: [...COLOURS.flatMap((c) => [`${c} box`, `${c} pillar`]), ...COLOURS],
};
const metres = (axis: string) => ({
  type: 'number',
  description: `${axis}, metres, in the frame the task gives points in (your pose's)`,
  minimum: -50,
  maximum: 50,
});
const object = (
  properties: JsonSchemaObject['properties'],
  required: string[] = [],
): JsonSchemaObject => ({
  type: 'object',
  properties,
  ...(required.length === 0 ? {} : { required }),
  additionalProperties: false,
});

/**
 * The skills as tools: short descriptions (a small model reads every word of them on every
 * request) and plain JSON Schemas (no unions: a grammar is built from them).
 */
export const SKILL_TOOLS: Readonly<Record<SkillName, AgentTool>> = {
  look: {
    name: 'look',
    description:
      'See what the camera shows now: coloured objects (distance, bearing) and how far the floor is clear ahead, left and right. around=true turns a full circle to look everywhere.',
    inputSchema: object({ around: { type: 'boolean', description: 'look all round' } }),
    // with `around` it turns a full circle
    motion: true,
  },
  find: {
    name: 'find',
    description:
      'Turn on the spot until the named thing is in view, then face it. Says if it is not here.',
    inputSchema: object({ target }, ['target']),
    motion: true,
  },
  go_to: {
    name: 'go_to',
    description:
      'Drive to a named thing and stop about 25 cm before it, avoiding what the camera sees. Looks for it first if needed.',
    inputSchema: object({ target }, ['target']),
    motion: true,
  },
  go_to_point: {
    name: 'go_to_point',
    description: 'Drive to the point (x, y), avoiding what the camera sees.',
    inputSchema: object({ x: metres('x'), y: metres('y') }, ['x', 'y']),
    motion: true,
  },
  face: {
    name: 'face',
    description: 'Turn on the spot to face a named thing.',
    inputSchema: object({ target }, ['target']),
    motion: true,
  },
  explore: {
    name: 'explore',
    description: 'Drive toward the nearest part of the place not seen yet; says what is new.',
    inputSchema: object({}),
    motion: true,
  },
  where_is: {
    name: 'where_is',
    description: 'Where a named thing was seen, from memory (no motion).',
    inputSchema: object({ target }, ['target']),
    motion: false,
  },
  what_have_you_seen: {
    name: 'what_have_you_seen',
    description: 'Everything seen so far, from memory (no motion).',
    inputSchema: object({}),
    motion: false,
  },
  go_back: {
    name: 'go_back',
    description: 'Drive back to where you started.',
    inputSchema: object({}),
    motion: true,
  },
  move: {
    name: 'move',
    description: 'Drive straight: cm > 0 forward, cm < 0 backward.',
    inputSchema: object(
      { cm: { type: 'number', description: 'distance, cm', minimum: -500, maximum: 500 } },
      ['cm'],
    ),
    motion: true,
  },
  turn: {
    name: 'turn',
    description: 'Turn on the spot: degrees > 0 to the left, < 0 to the right.',
    inputSchema: object(
      { degrees: { type: 'number', description: 'angle, degrees', minimum: -360, maximum: 360 } },
      ['degrees'],
    ),
    motion: true,
  },
};
