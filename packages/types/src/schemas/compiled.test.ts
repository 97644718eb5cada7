import { it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { z } from 'zod';
import { anyInput, jsonSchemaOf, validObject } from './schema-inputs.fixture.js';

// zod's compiled parse against its ordinary one on constructs beyond those today's call schemas
// use (a call schema added later may use any of them) and on the inputs a hand-written fast path
// gets wrong: code points, -0, unsafe integers, objects that are not plain, a throwing getter,
// a `__proto__` key. The HAL boundary relies on the two agreeing.

const CONSTRUCTS: Record<string, z.ZodType> = {
  'exclusive and inclusive bounds, ints, lengths, literals, booleans and a nested object': z.object(
    {
      a: z.number().gt(-5).lt(5),
      b: z.number().int().min(-3).max(3).optional(),
      c: z.string().min(3).max(6),
      d: z.string().length(2).optional(),
      e: z.literal('x'),
      f: z.boolean(),
      g: z.object({ h: z.number().min(1).max(1), i: z.enum(['p', 'q']).optional() }).optional(),
      j: z.int().lt(10),
    },
  ),
  'stacked bounds that tie, inclusive against exclusive': z.object({
    n: z.number().gte(1).gt(1).gt(0).lte(2).lt(3).max(2).lt(2),
    m: z.number().nonnegative().nonpositive(),
  }),
  'a string measured in code points, not UTF-16 units': z.object({
    s: z.string().min(2).max(3),
    t: z.string().length(1).optional(),
  }),
  'a preprocessed field': z.object({ s: z.preprocess((v) => String(v).trim(), z.string().max(4)) }),
  'an object without keys': z.object({}),
};

/** What a parse came to: the output, the issues, or what it threw. */
function outcome(schema: z.ZodType, input: unknown): unknown {
  try {
    const parsed = schema.safeParse(input);
    return parsed.success ? { data: parsed.data } : { issues: parsed.error.issues };
  } catch (thrown) {
    return { threw: String(thrown) };
  }
}

describe('a schema compiled by zod', () => {
  for (const [what, schema] of Object.entries(CONSTRUCTS)) {
    const compiled = z.compile(schema, { strict: true });

    it.prop([anyInput(schema)], { numRuns: 1500 })(
      `parses as the ordinary schema does, for ${what}`,
      (input) => {
        expect(outcome(compiled, input)).toStrictEqual(outcome(schema, input));
      },
    );

    it.prop([validObject(jsonSchemaOf(schema))], { numRuns: 300 })(
      `accepts the valid inputs with the ordinary output, for ${what}`,
      (input) => {
        expect(compiled.parse(input)).toStrictEqual(schema.parse(input));
      },
    );
  }

  const schema = z.object({
    n: z.number().gt(0).optional(),
    i: z.number().int().optional(),
    s: z.string().min(2).max(3).optional(),
    x: z.number(),
  });
  const compiled = z.compile(schema, { strict: true });
  class Point {
    x = 1;
  }
  const EDGES: Record<string, unknown> = {
    NaN: { x: Number.NaN },
    Infinity: { x: Infinity },
    '-Infinity': { x: -Infinity },
    '-0 below an exclusive 0': { x: 1, n: -0 },
    '-0': { x: -0 },
    'an unsafe integer': { x: 1, i: 2 ** 53 },
    'two emoji, two characters': { x: 1, s: '\u{1F600}\u{1F600}' },
    'one emoji, one character': { x: 1, s: '\u{1F600}' },
    'four characters': { x: 1, s: 'abcd' },
    'a class instance': new Point(),
    'an array': [1],
    'an object without a prototype': Object.assign(Object.create(null) as object, { x: 1 }),
    'a throwing getter': Object.defineProperty({}, 'x', {
      enumerable: true,
      get() {
        throw new Error('no x');
      },
    }),
    'a __proto__ own key': JSON.parse('{"x": 1, "__proto__": {"polluted": true}}') as unknown,
  };
  for (const [what, input] of Object.entries(EDGES)) {
    it(`gives the ordinary answer for ${what}`, () => {
      expect(outcome(compiled, input)).toStrictEqual(outcome(schema, input));
    });
  }

  it('does not copy a __proto__ own key into the output', () => {
    const output = compiled.parse(EDGES['a __proto__ own key']) as Record<string, unknown>;
    expect(output).toStrictEqual({ x: 1 });
    expect(Object.getPrototypeOf(output)).toBe(Object.prototype);
    expect(output['polluted']).toBeUndefined();
  });
});
