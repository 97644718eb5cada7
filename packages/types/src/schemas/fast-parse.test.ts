import { it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { z } from 'zod';
import { compileFastParse } from './fast-parse.js';
import { anyInput, jsonSchemaOf, validObject } from './schema-inputs.fixture.js';

// The constructs the fast path models, beyond those today's call schemas happen to use (a call
// schema added later may use any of them), held to zod the same way as the call schemas are in
// fast-parse.property.test.ts; and the constructs it must leave to zod.

const MODELLED: Record<string, z.ZodType> = {
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
  'an object without keys': z.object({}),
};

describe('compileFastParse', () => {
  for (const [what, schema] of Object.entries(MODELLED)) {
    const parse = compileFastParse(schema);

    it(`models ${what}`, () => {
      expect(parse).toBeTypeOf('function');
    });

    it.prop([anyInput(schema)], { numRuns: 1500 })(
      `accepts only what zod accepts, with zod's output, for ${what}`,
      (input) => {
        const result = schema.safeParse(input);
        const output = parse?.(input);
        if (output !== undefined) {
          expect(result.success).toBe(true);
          expect(output).toStrictEqual(result.data);
        }
        if (!result.success) expect(output).toBeUndefined();
      },
    );

    it.prop([validObject(jsonSchemaOf(schema))], { numRuns: 300 })(
      `takes the valid inputs itself for ${what}`,
      (input) => {
        expect(parse?.(input)).toStrictEqual(schema.parse(input));
      },
    );
  }

  it('counts a string in code points as zod does: two emoji are two characters', () => {
    const parse = compileFastParse(MODELLED['a string measured in code points, not UTF-16 units']!);
    expect(parse?.({ s: '\u{1F600}\u{1F600}' })).toStrictEqual({ s: '\u{1F600}\u{1F600}' });
    expect(parse?.({ s: '\u{1F600}' })).toBeUndefined();
    expect(parse?.({ s: 'ab\u{1F600}' })).toStrictEqual({ s: 'ab\u{1F600}' });
    expect(parse?.({ s: 'abcd' })).toBeUndefined();
  });

  it('refuses NaN, infinities, -0 below an exclusive 0 and unsafe integers', () => {
    const parse = compileFastParse(
      z.object({ n: z.number().gt(0).optional(), i: z.number().int().optional(), x: z.number() }),
    );
    expect(parse?.({ x: Number.NaN })).toBeUndefined();
    expect(parse?.({ x: Infinity })).toBeUndefined();
    expect(parse?.({ x: -Infinity })).toBeUndefined();
    expect(parse?.({ x: 1, n: -0 })).toBeUndefined();
    expect(parse?.({ x: 1, i: 2 ** 53 })).toBeUndefined();
    expect(parse?.({ x: -0 })).toStrictEqual({ x: -0 });
  });

  it('leaves objects that are not plain, and objects with a throwing getter, to zod', () => {
    const parse = compileFastParse(z.object({ x: z.number() }));
    class Point {
      x = 1;
    }
    const throwing = Object.defineProperty({}, 'x', {
      enumerable: true,
      get() {
        throw new Error('no x');
      },
    });
    expect(parse?.(new Point())).toBeUndefined();
    expect(parse?.(throwing)).toBeUndefined();
    expect(parse?.([1])).toBeUndefined();
    expect(parse?.(Object.assign(Object.create(null), { x: 1 }))).toStrictEqual({ x: 1 });
  });

  it('does not copy a __proto__ own key, as zod strips unknown keys', () => {
    const parse = compileFastParse(z.object({ x: z.number() }));
    const input = JSON.parse('{"x": 1, "__proto__": {"polluted": true}}') as unknown;
    const output = parse?.(input) as Record<string, unknown>;
    expect(output).toStrictEqual({ x: 1 });
    expect(Object.getPrototypeOf(output)).toBe(Object.prototype);
    expect(output['polluted']).toBeUndefined();
  });

  const FALLBACKS: Record<string, z.ZodType> = {
    'a preprocessed field': z.object({ s: z.preprocess(String, z.string()) }),
    'a transform': z.object({ n: z.number().transform((n) => n * 2) }),
    'a default': z.object({ n: z.number().default(1) }),
    'an optional default': z.object({ n: z.number().default(1).optional() }),
    'a refinement': z.object({ n: z.number().refine((n) => n !== 3) }),
    'a refinement of the object': z.object({ n: z.number() }).refine((o) => o.n > 0),
    'a union': z.object({ u: z.union([z.number(), z.string()]) }),
    'a strict object': z.strictObject({ n: z.number() }),
    'a loose object': z.looseObject({ n: z.number() }),
    'a catchall': z.object({ n: z.number() }).catchall(z.string()),
    'a coerced number': z.object({ n: z.coerce.number() }),
    'a string format': z.object({ s: z.email() }),
    'a regex': z.object({ s: z.string().regex(/^a/) }),
    'a trim': z.object({ s: z.string().trim() }),
    'a multiple of': z.object({ n: z.number().multipleOf(2) }),
    'an int32': z.object({ n: z.int32() }),
    'a nullable': z.object({ n: z.number().nullable() }),
    'an array': z.object({ a: z.array(z.number()) }),
    'an exact optional': z.object({ n: z.exactOptional(z.number()) }),
    'a literal undefined': z.object({ u: z.literal(undefined) }),
    'a readonly field': z.object({ o: z.object({}).readonly() }),
    'a record': z.record(z.string(), z.number()),
    'a symbol key': z.object({ [Symbol('s')]: z.number() }),
  };

  for (const [what, schema] of Object.entries(FALLBACKS)) {
    it(`leaves a schema with ${what} wholly to zod`, () => {
      expect(compileFastParse(schema)).toBeUndefined();
    });
  }
});
