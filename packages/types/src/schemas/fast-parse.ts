import type { z } from 'zod';

/*
 * A hand-checked path for zod schemas, built once per schema from the schema's own definition
 * (`schema._zod.def` and its checks): every public HAL call is validated, and zod's `safeParse`
 * builds a payload object per schema node and copies the input, which makes it most of the
 * allocation the HAL layer adds to a call. This path checks the simple shapes the call schemas
 * are made of (an object of numbers with bounds and `int()`, strings with length limits, enums,
 * literals, booleans, `.optional()`) and builds the same output zod would: the known keys only,
 * unknown ones stripped. It only ever accepts: whatever it is not sure of goes to zod, which stays
 * the definition and gives every error. A schema with any part it does not model (preprocess,
 * transform, default, refine, union, catchall, a check kind it does not know...) gets no fast
 * path at all. fast-parse.property.test.ts (every call schema) and fast-parse.test.ts (every
 * construct modelled) hold the two equal: whatever this path accepts, zod accepts with an equal
 * output, and whatever zod refuses, this path refuses.
 */

/** A checked value, or {@link UNSURE}: the value may or may not be valid, zod must decide. */
const UNSURE: unique symbol = Symbol('unsure');
type Node = (value: unknown) => unknown;

/** The definition fields this module reads; zod's own types name each kind's fields. */
interface Internals {
  readonly def: z.core.$ZodTypeDef & Readonly<Record<string, unknown>>;
  readonly traits: ReadonlySet<string>;
  readonly values?: ReadonlySet<unknown> | undefined;
}
const internals = (schema: unknown): Internals => (schema as { _zod: Internals })._zod;

/** The checks zod runs for a schema: the schema itself when it is a check (`z.int()`), then its own. */
function checksOf(zod: Internals): z.core.$ZodCheckDef[] {
  const own = (zod.def.checks ?? []).map(
    (check) => internals(check).def as unknown as z.core.$ZodCheckDef,
  );
  return zod.traits.has('$ZodCheck') ? [zod.def as unknown as z.core.$ZodCheckDef, ...own] : own;
}

/** A number's bounds folded to the tightest of each side (exclusive wins a tie). */
interface Bound {
  value: number;
  inclusive: boolean;
}
function tighter(current: Bound | undefined, next: Bound, lower: boolean): Bound {
  if (current === undefined) return next;
  if (next.value === current.value)
    return { value: next.value, inclusive: current.inclusive && next.inclusive };
  return (lower ? next.value > current.value : next.value < current.value) ? next : current;
}

function numberNode(checks: readonly z.core.$ZodCheckDef[]): Node | undefined {
  let min: Bound | undefined;
  let max: Bound | undefined;
  let int = false;
  for (const check of checks) {
    if (check.check === 'greater_than' || check.check === 'less_than') {
      const { value, inclusive } = check as z.core.$ZodCheckGreaterThanDef;
      if (typeof value !== 'number' || Number.isNaN(value)) return undefined;
      if (check.check === 'greater_than') min = tighter(min, { value, inclusive }, true);
      else max = tighter(max, { value, inclusive }, false);
    } else if (check.check === 'number_format') {
      // `int()`: an integer within the safe range; other formats (int32, float32, ...) go to zod
      if ((check as z.core.$ZodCheckNumberFormatDef).format !== 'safeint') return undefined;
      int = true;
    } else {
      return undefined;
    }
  }
  const lo = min?.value ?? -Infinity;
  const loInclusive = min?.inclusive ?? true;
  const hi = max?.value ?? Infinity;
  const hiInclusive = max?.inclusive ?? true;
  return (value) => {
    // zod's number: a finite number (NaN and +-Infinity are refused); then every check
    if (typeof value !== 'number' || !Number.isFinite(value)) return UNSURE;
    if (int && !Number.isSafeInteger(value)) return UNSURE;
    if (loInclusive ? !(value >= lo) : !(value > lo)) return UNSURE;
    if (hiInclusive ? !(value <= hi) : !(value < hi)) return UNSURE;
    return value;
  };
}

/** Unicode code points, as zod measures a string: a lone surrogate counts as one. */
function codePoints(text: string): number {
  let count = text.length;
  for (let i = 0; i < text.length - 1; i++) {
    if ((text.charCodeAt(i) & 0xfc00) === 0xd800 && (text.charCodeAt(i + 1) & 0xfc00) === 0xdc00) {
      count--;
      i++;
    }
  }
  return count;
}

function stringNode(checks: readonly z.core.$ZodCheckDef[]): Node | undefined {
  let min = 0;
  let max = Infinity;
  for (const check of checks) {
    if (check.check === 'min_length') {
      min = Math.max(min, (check as z.core.$ZodCheckMinLengthDef).minimum);
    } else if (check.check === 'max_length') {
      max = Math.min(max, (check as z.core.$ZodCheckMaxLengthDef).maximum);
    } else if (check.check === 'length_equals') {
      const { length } = check as z.core.$ZodCheckLengthEqualsDef;
      min = Math.max(min, length);
      max = Math.min(max, length);
    } else {
      // formats, regexes, trims and case changes go to zod
      return undefined;
    }
  }
  if (Number.isNaN(min) || Number.isNaN(max)) return undefined;
  return (value) => {
    if (typeof value !== 'string') return UNSURE;
    // a code point is one or two UTF-16 units: count them only when the units leave it in doubt
    const units = value.length;
    if (units <= max && units >= 2 * min) return value;
    const length = codePoints(value);
    return length >= min && length <= max ? value : UNSURE;
  };
}

function objectNode(def: z.core.$ZodObjectDef): Node | undefined {
  // a catchall (strictObject, looseObject, .catchall()) keeps or refuses unknown keys: zod decides
  if (def.catchall !== undefined) return undefined;
  const shape = def.shape;
  if (Object.getOwnPropertySymbols(shape).length > 0) return undefined;
  const keys = Object.keys(shape);
  // zod skips a `__proto__` key of the shape; leave such a schema to it
  if (keys.includes('__proto__')) return undefined;
  const fields: { key: string; optional: boolean; node: Node }[] = [];
  for (const key of keys) {
    let field: unknown = shape[key];
    let zod = internals(field);
    const optional = zod.def.type === 'optional';
    if (optional) {
      // exactOptional refuses an explicit undefined; a defaulted inner substitutes a value
      if (zod.traits.has('$ZodExactOptional') || checksOf(zod).length > 0) return undefined;
      field = (zod.def as unknown as z.core.$ZodOptionalDef).innerType;
      zod = internals(field);
      if (zod.def.type === 'optional') return undefined;
    }
    const node = nodeOf(field);
    if (node === undefined) return undefined;
    fields.push({ key, optional, node });
  }
  return (value) => {
    // a plain object (or one without a prototype): anything else, zod decides
    if (typeof value !== 'object' || value === null) return UNSURE;
    const proto: unknown = Object.getPrototypeOf(value);
    if (proto !== Object.prototype && proto !== null) return UNSURE;
    const input = value as Record<string, unknown>;
    const out: Record<string, unknown> = {};
    for (const { key, optional, node } of fields) {
      // as zod: presence is `key in input`; a present optional key keeps an explicit undefined
      if (optional) {
        if (!(key in input)) continue;
        const field = input[key];
        if (field === undefined) {
          out[key] = undefined;
          continue;
        }
        const checked = node(field);
        if (checked === UNSURE) return UNSURE;
        out[key] = checked;
      } else {
        // no node here accepts undefined, so an absent required key is refused by its node
        const checked = node(input[key]);
        if (checked === UNSURE) return UNSURE;
        out[key] = checked;
      }
    }
    return out;
  };
}

/** The checking node of a schema, or undefined when it has a part this path does not model. */
function nodeOf(schema: unknown): Node | undefined {
  const zod = internals(schema);
  const def = zod.def;
  if (def['coerce'] === true) return undefined;
  const checks = checksOf(zod);
  switch (def.type) {
    case 'number':
      return numberNode(checks);
    case 'string':
      return stringNode(checks);
    case 'boolean':
      return checks.length > 0
        ? undefined
        : (value) => (typeof value === 'boolean' ? value : UNSURE);
    case 'enum':
    case 'literal': {
      // the very set zod's enum and literal look a value up in
      // (one that takes undefined would make an absent key look present: zod decides those)
      const values = zod.values;
      if (values === undefined || values.has(undefined) || checks.length > 0) return undefined;
      return (value) => (values.has(value) ? value : UNSURE);
    }
    case 'object':
      return checks.length > 0 ? undefined : objectNode(def as unknown as z.core.$ZodObjectDef);
    default:
      return undefined;
  }
}

/**
 * Checks an input against a schema the fast way: the output zod would give, or undefined when
 * the input may be invalid (then zod decides, and gives the error).
 */
export type FastParse = (input: unknown) => unknown;

/**
 * The fast path of a zod schema, built from its definition; undefined when the schema has a part
 * this path does not model (every input then goes to zod). The returned function never throws
 * and only returns an output zod would return for the same input.
 */
export function compileFastParse(schema: z.ZodType): FastParse | undefined {
  const node = nodeOf(schema);
  if (node === undefined) return undefined;
  return (input) => {
    try {
      const checked = node(input);
      return checked === UNSURE ? undefined : checked;
    } catch {
      // a throwing getter or proxy: zod decides (and meets the same throw)
      return undefined;
    }
  };
}

/** The fast paths of a set of schemas, by name; a schema this path does not model has none. */
export function compileFastParsers<S extends Readonly<Record<string, z.ZodType>>>(
  schemas: S,
): { readonly [K in keyof S]?: FastParse } {
  const parsers: { [K in keyof S]?: FastParse } = {};
  for (const [name, schema] of Object.entries(schemas)) {
    const parse = compileFastParse(schema);
    if (parse !== undefined) parsers[name as keyof S] = parse;
  }
  return parsers;
}
