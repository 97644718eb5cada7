// Turns the tools' JSON Schemas (as every model gets them from @hal/tools) into the one schema
// the grammar is built from: a tool call `{"tool": NAME, "arguments": {...}}` for each tool, or
// `{"answer": TEXT}` to finish. The grammar can express shapes and types, not every constraint.
import type { ChatTool } from '@hal/agent';
import type { GbnfJsonOneOfSchema } from 'node-llama-cpp';
import { LocalModelError } from './errors.js';

type Json = Record<string, unknown>;

/**
 * Keywords the grammar leaves to the tool's own validation (which runs on every call): numeric
 * bounds and documentation. A number the grammar lets through may still be out of range, and
 * the tool's result then says so.
 */
const CHECKED_AFTER = new Set([
  'minimum',
  'maximum',
  'exclusiveMinimum',
  'exclusiveMaximum',
  'multipleOf',
  'title',
  'default',
  'examples',
  '$schema',
]);

const KEPT = new Set([
  'type',
  'description',
  'enum',
  'const',
  'properties',
  'required',
  'additionalProperties',
  'minProperties',
  'maxProperties',
  'items',
  'prefixItems',
  'minItems',
  'maxItems',
  'minLength',
  'maxLength',
  'format',
  'oneOf',
  'anyOf',
]);

/**
 * The largest count the grammar writes as a counted repetition (`{0,N}`). llama.cpp expands a
 * counted repetition into one rule per count and refuses a grammar where a repetition's count
 * times the rules before it in its sequence reaches 2000 (its MAX_REPETITION_THRESHOLD): the
 * `log` tool's `maxLength: 2000` alone is refused. A bound above this is left out of the grammar
 * and checked after generation instead: by the tool's own validation for its arguments, and by
 * the provider for the answer (cut to its length).
 */
export const MAX_COUNTED_REPETITION = 256;

/** Keywords that become counted repetitions in the grammar. */
const COUNTED = new Set([
  'minLength',
  'maxLength',
  'minItems',
  'maxItems',
  'minProperties',
  'maxProperties',
]);

const TYPES = new Set(['string', 'number', 'integer', 'boolean', 'null', 'object', 'array']);
const FORMATS = new Set(['date-time', 'time', 'date']);

const isObject = (value: unknown): value is Json =>
  typeof value === 'object' && value !== null && !Array.isArray(value);

function convert(schema: unknown, path: string): Json {
  const refuse = (why: string): never => {
    throw new LocalModelError('SCHEMA_UNSUPPORTED', `${path}: ${why}`);
  };
  if (!isObject(schema)) return refuse('a schema must be an object');
  const out: Json = {};
  for (const [key, value] of Object.entries(schema)) {
    if (CHECKED_AFTER.has(key)) continue;
    if (!KEPT.has(key)) return refuse(`"${key}" cannot be expressed by the grammar`);
    // a count too large for llama.cpp's grammar parser is left to the tool's validation
    if (COUNTED.has(key) && typeof value === 'number' && value > MAX_COUNTED_REPETITION) continue;
    switch (key) {
      case 'type': {
        const types = Array.isArray(value) ? value : [value];
        if (types.some((t) => typeof t !== 'string' || !TYPES.has(t)))
          return refuse(`type ${JSON.stringify(value)} is not one the grammar knows`);
        if (Array.isArray(value) && types.some((t) => t === 'object' || t === 'array'))
          return refuse('a list of types may only hold string, number, integer, boolean, null');
        out[key] = value;
        break;
      }
      case 'format':
        if (typeof value !== 'string' || !FORMATS.has(value))
          return refuse(`format ${JSON.stringify(value)} cannot be expressed by the grammar`);
        out[key] = value;
        break;
      case 'properties': {
        if (!isObject(value)) return refuse('"properties" must be an object');
        out[key] = Object.fromEntries(
          Object.entries(value).map(([name, sub]) => [name, convert(sub, `${path}.${name}`)]),
        );
        break;
      }
      case 'additionalProperties':
        out[key] = typeof value === 'boolean' ? value : convert(value, `${path}[*]`);
        break;
      case 'items':
        out[key] = convert(value, `${path}[]`);
        break;
      case 'prefixItems':
      case 'oneOf':
      case 'anyOf': {
        if (!Array.isArray(value)) return refuse(`"${key}" must be an array`);
        // anyOf and oneOf are the same alternation to a grammar
        const name = key === 'prefixItems' ? key : 'oneOf';
        out[name] = value.map((sub, i) => convert(sub, `${path}.${key}[${i}]`));
        break;
      }
      default:
        out[key] = value;
    }
  }
  if (out['type'] === 'object' && out['additionalProperties'] === undefined)
    out['additionalProperties'] = false;
  return out;
}

/** The longest answer the grammar allows, characters. */
export const DEFAULT_ANSWER_MAX_LENGTH = 240;

/**
 * The grammar's schema for `tools`. Throws a LocalModelError SCHEMA_UNSUPPORTED naming the first
 * tool whose parameters use something the grammar cannot express (a `pattern`, `allOf`, `not`,
 * `$ref`, an unknown keyword...). Lengths and counts above {@link MAX_COUNTED_REPETITION} are
 * left out (see there); so is an `answerMaxLength` above it, which the provider then checks.
 */
export function replySchema(
  tools: readonly ChatTool[],
  answerMaxLength = DEFAULT_ANSWER_MAX_LENGTH,
  shape: { answer: boolean } = { answer: true },
): GbnfJsonOneOfSchema {
  const calls = tools.map(({ function: fn }) => {
    let parameters: Json;
    try {
      parameters = convert(fn.parameters, 'parameters');
    } catch (error) {
      if (!(error instanceof LocalModelError)) throw error;
      throw new LocalModelError(
        'SCHEMA_UNSUPPORTED',
        `tool "${fn.name}": its schema cannot be expressed as a grammar (${error.message})`,
        { details: { tool: fn.name } },
      );
    }
    return {
      type: 'object',
      properties: { tool: { const: fn.name }, arguments: parameters },
      required: ['tool', 'arguments'],
      additionalProperties: false,
    };
  });
  const answer = {
    type: 'object',
    properties: {
      answer:
        answerMaxLength > MAX_COUNTED_REPETITION
          ? { type: 'string' }
          : { type: 'string', maxLength: answerMaxLength },
    },
    required: ['answer'],
    additionalProperties: false,
  };
  // The shapes are checked above; node-llama-cpp's schema type is a deep literal type.
  if (!shape.answer && calls.length === 0)
    throw new LocalModelError('CONFIG', 'a reply that must call a tool needs a tool to call');
  return { oneOf: shape.answer ? [...calls, answer] : calls } as unknown as GbnfJsonOneOfSchema;
}
