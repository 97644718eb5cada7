import { fc } from '@fast-check/vitest';
import { z } from 'zod';

/*
 * Inputs for a zod schema, derived from the schema itself, for the fast path's property test:
 * hostile ones (anything, values at and around every limit zod records for a field, wrong types,
 * missing, extra and `__proto__` keys) and valid ones (what a caller ordinarily passes). The
 * limits come from zod's JSON Schema of the schema (`z.toJSONSchema`, what tool definitions are
 * made of), not from the fast path's reading of the definition, so a misreading there shows here.
 */

/** The part of a JSON Schema these inputs are made from. */
interface Json {
  type?: string;
  minimum?: number;
  maximum?: number;
  exclusiveMinimum?: number;
  exclusiveMaximum?: number;
  minLength?: number;
  maxLength?: number;
  enum?: unknown[];
  const?: unknown;
  properties?: Record<string, Json>;
  required?: string[];
}

/** The JSON Schema of a zod schema, as its input. */
export function jsonSchemaOf(schema: z.ZodType): Json {
  return z.toJSONSchema(schema, { unrepresentable: 'any', io: 'input' }) as Json;
}

const bits = new Float64Array(1);
const word = new BigInt64Array(bits.buffer);
/** The next double above (`up`) or below `value`. */
function nextDouble(value: number, up: boolean): number {
  if (!Number.isFinite(value)) return value;
  if (value === 0) return up ? Number.MIN_VALUE : -Number.MIN_VALUE;
  bits[0] = value;
  word[0]! += value > 0 === up ? 1n : -1n;
  return bits[0]!;
}

const NUMBERS = [
  Number.NaN,
  Infinity,
  -Infinity,
  0,
  -0,
  0.5,
  1,
  -1,
  Number.MIN_VALUE,
  Number.MAX_VALUE,
  Number.MAX_SAFE_INTEGER,
  Number.MAX_SAFE_INTEGER + 1,
  Number.MIN_SAFE_INTEGER - 1,
  2 ** 53,
  1e21,
];
const WRONG_TYPES = ['', '1', 'NaN', true, false, null, undefined, 1n, {}, [], [1], new Date(0)];

/** Numbers at, just inside and just outside each limit, and the usual suspects. */
function numberEdges(json: Json): unknown[] {
  const limits = [json.minimum, json.maximum, json.exclusiveMinimum, json.exclusiveMaximum].filter(
    (v): v is number => typeof v === 'number' && Number.isFinite(v),
  );
  const near = limits.flatMap((v) => [
    v,
    nextDouble(v, true),
    nextDouble(v, false),
    v + 1,
    v - 1,
    v + 0.5,
    v - 0.5,
    -v,
    Math.round(v),
    Math.trunc(v) + 0.5,
  ]);
  return [...near, ...NUMBERS];
}

const EMOJI = '\u{1F600}'; // two UTF-16 units, one code point
const UNITS = fc.constantFrom('a', ' ', '\u00e9', EMOJI, '\ud83d', '\ude00', '\u0000', '\u2028');
/** Strings of every length in units and in code points around each length limit. */
function stringEdges(json: Json): unknown[] {
  const limits = [json.minLength, json.maxLength].filter(
    (v): v is number => typeof v === 'number' && Number.isFinite(v),
  );
  const out: unknown[] = ['', 'a', EMOJI, '\ud83d', `${EMOJI}\ude00`];
  for (const limit of limits) {
    for (const n of [limit - 1, limit, limit + 1, Math.ceil(limit / 2), 2 * limit]) {
      if (n < 0) continue;
      out.push('a'.repeat(n), EMOJI.repeat(n), `${EMOJI.repeat(Math.max(0, n - 1))}a`);
      out.push('\ud83d'.repeat(n), `${'a'.repeat(Math.max(0, n - 1))}${EMOJI}`);
    }
  }
  return out;
}

const anything = fc.anything({
  withNullPrototype: true,
  withBoxedValues: true,
  withBigInt: true,
  withSparseArray: true,
  stringUnit: 'binary',
});

/** A hostile value for a JSON Schema, as one field of an object or the whole input. */
function hostileValue(json: Json): fc.Arbitrary<unknown> {
  const wrong = fc.constantFrom(...WRONG_TYPES);
  if (json.enum !== undefined || 'const' in json) {
    const values = json.enum ?? [json.const];
    const near = values.flatMap((v) =>
      typeof v === 'string' ? [v.toUpperCase(), `${v} `, v.slice(1), new String(v)] : [],
    );
    return fc.oneof({ weight: 3, arbitrary: fc.constantFrom(...values, ...near) }, wrong, anything);
  }
  switch (json.type) {
    case 'object':
      return fc.oneof({ weight: 4, arbitrary: hostileObject(json) }, anything);
    case 'number':
    case 'integer':
      return fc.oneof(
        { weight: 3, arbitrary: fc.constantFrom(...numberEdges(json)) },
        fc.double(),
        fc.integer(),
        wrong,
        anything,
      );
    case 'string':
      return fc.oneof(
        { weight: 3, arbitrary: fc.constantFrom(...stringEdges(json)) },
        fc.string({ unit: UNITS, maxLength: 2 * (json.maxLength ?? 8) + 2 }),
        wrong,
        anything,
      );
    default:
      return fc.oneof(wrong, anything);
  }
}

const EXTRA_KEYS = fc.oneof(
  fc.constantFrom('__proto__', 'constructor', 'toString', 'hasOwnProperty', 'extra', 'R', ''),
  fc.string(),
);

/**
 * An object for an object schema: each known key hostile, valid or undefined, present or absent,
 * extra keys (a `__proto__` own key among them), sometimes without a prototype or through JSON.
 */
function hostileObject(json: Json): fc.Arbitrary<unknown> {
  const fields = Object.fromEntries(
    Object.entries(json.properties ?? {}).map(([key, field]) => [
      key,
      fc.oneof(hostileValue(field), validValue(field), fc.constant(undefined)),
    ]),
  );
  const known = fc.record(fields, { requiredKeys: [] });
  const extra = fc.dictionary(EXTRA_KEYS, fc.jsonValue(), { maxKeys: 3 });
  return fc
    .tuple(known, extra, fc.constantFrom('plain', 'extra-first', 'null-prototype', 'json'))
    .map(([ownKeys, extraKeys, form]) => {
      const merged: Record<string, unknown> = {};
      const order = form === 'extra-first' ? [extraKeys, ownKeys] : [ownKeys, extraKeys];
      // defineProperty, so a `__proto__` key becomes an own key rather than the prototype
      for (const part of order)
        for (const [k, v] of Object.entries(part))
          Object.defineProperty(merged, k, {
            value: v,
            enumerable: true,
            writable: true,
            configurable: true,
          });
      if (form === 'null-prototype') return Object.assign(Object.create(null), merged) as unknown;
      if (form === 'json') {
        try {
          return JSON.parse(JSON.stringify(merged)) as unknown;
        } catch {
          return merged; // a bigint: not JSON
        }
      }
      return merged;
    });
}

/** A valid value for a JSON Schema of the shapes the call schemas use. */
function validValue(json: Json): fc.Arbitrary<unknown> {
  if (json.enum !== undefined) return fc.constantFrom(...json.enum);
  if ('const' in json) return fc.constant(json.const);
  switch (json.type) {
    case 'number':
    case 'integer': {
      const min = json.minimum ?? json.exclusiveMinimum ?? -1e6;
      const max = json.maximum ?? json.exclusiveMaximum ?? 1e6;
      const inRange = (v: number) =>
        (json.exclusiveMinimum === undefined || v > json.exclusiveMinimum) &&
        (json.exclusiveMaximum === undefined || v < json.exclusiveMaximum);
      const numbers =
        json.type === 'integer'
          ? fc.integer({ min: Math.ceil(min), max: Math.floor(max) })
          : fc.double({ min, max, noNaN: true, noDefaultInfinity: true });
      return numbers.filter(inRange);
    }
    case 'string':
      // one UTF-16 unit per character, so lengths are the same in units and code points
      return fc.string({ minLength: json.minLength ?? 0, maxLength: json.maxLength ?? 40 });
    case 'boolean':
      return fc.boolean();
    case 'object':
      return validObject(json);
    default:
      throw new Error(`no valid values for a JSON Schema of type ${String(json.type)}`);
  }
}

/**
 * A valid object for an object schema, as a caller passes it: every required key, the optional
 * ones absent, present or present and undefined (as a HAL passes an omitted argument on).
 */
export function validObject(json: Json): fc.Arbitrary<Record<string, unknown>> {
  const required = new Set(json.required ?? []);
  const fields = Object.fromEntries(
    Object.entries(json.properties ?? {}).map(([key, field]) => [
      key,
      required.has(key) ? validValue(field) : fc.oneof(validValue(field), fc.constant(undefined)),
    ]),
  );
  return fc.record(fields, { requiredKeys: [...required] });
}

/**
 * A valid object with one field made hostile, removed or set to undefined: the inputs nearest
 * to acceptance, where a fast path that is too lenient on one field shows.
 */
function oneFieldOff(json: Json): fc.Arbitrary<unknown> {
  const keys = Object.keys(json.properties ?? {});
  if (keys.length === 0) return validObject(json);
  return fc.tuple(validObject(json), fc.constantFrom(...keys)).chain(([object, key]) =>
    fc
      .oneof(
        { weight: 4, arbitrary: hostileValue(json.properties![key]!).map((v) => ({ v })) },
        fc.constant({ v: undefined }),
        fc.constant(undefined),
      )
      .map((change) => {
        const copy: Record<string, unknown> = { ...object };
        if (change === undefined) delete copy[key];
        else copy[key] = change.v;
        return copy;
      }),
  );
}

/** Every input the property test tries on a schema. */
export function anyInput(schema: z.ZodType): fc.Arbitrary<unknown> {
  const json = jsonSchemaOf(schema);
  return fc.oneof(
    { weight: 3, arbitrary: hostileValue(json) },
    { weight: json.type === 'object' ? 3 : 0, arbitrary: oneFieldOff(json) },
    anything,
  );
}
