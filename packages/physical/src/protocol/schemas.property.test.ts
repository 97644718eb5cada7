import { fc, it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { LED_PATTERNS, REPLY_SCHEMAS } from './schemas.js';
import type { Command } from './schemas.js';
import { byte, int, motionReplyFields, uint32 } from './reply-fields.fixture.js';

// Property tests of the reply decoders: any value is either a typed reply or a refusal (never an
// exception), unknown fields are dropped, null means absent, and a required field of the wrong
// type is always refused.

const commands = Object.keys(REPLY_SCHEMAS) as Command[];
const led = fc.record({ r: byte, g: byte, b: byte, pattern: fc.constantFrom(...LED_PATTERNS) });

/** Valid reply data of some commands: required fields, and optional ones. */
const shapes: Partial<
  Record<
    Command,
    {
      required: Record<string, fc.Arbitrary<unknown>>;
      optional: Record<string, fc.Arbitrary<unknown>>;
    }
  >
> = {
  heartbeat: {
    required: { uptime_ms: int, running: fc.boolean(), estop: fc.boolean() },
    optional: {},
  },
  move_steps: {
    required: { move_id: uint32 },
    optional: motionReplyFields,
  },
  stop: { required: { stopped: fc.boolean(), left_steps: int, right_steps: int }, optional: {} },
  set_led: { required: { led }, optional: {} },
  estop: { required: { estop: fc.constant(true), estop_reason: fc.string() }, optional: {} },
  reset_estop: {
    required: { estop: fc.constant(false), was_estopped: fc.boolean() },
    optional: {},
  },
};

const shaped = Object.entries(shapes) as Array<[Command, NonNullable<(typeof shapes)[Command]>]>;

/** A valid reply, the same with unknown fields added and some optional fields null. */
const replyArb = fc.constantFrom(...shaped).chain(([cmd, shape]) =>
  fc
    .record({
      required: fc.record(shape.required),
      optional: fc.record(shape.optional, { requiredKeys: [] }),
      nulls: fc.subarray(Object.keys(shape.optional)),
      unknown: fc.dictionary(
        fc.string({ maxLength: 8 }).filter((k) => !(k in shape.required) && !(k in shape.optional)),
        fc.jsonValue({ maxDepth: 1 }),
        { maxKeys: 3 },
      ),
    })
    .map(({ required, optional, nulls, unknown }) => {
      const clean: Record<string, unknown> = { ...required, ...optional };
      for (const k of nulls) delete clean[k];
      const sent = { ...unknown, ...clean, ...Object.fromEntries(nulls.map((k) => [k, null])) };
      return { cmd, clean, sent, required: Object.keys(shape.required) };
    }),
);

/** A value of another JSON type than `value`. */
function wrongType(value: unknown): unknown {
  if (typeof value === 'string') return 7;
  if (typeof value === 'number') return String(value);
  if (typeof value === 'boolean') return value ? 'true' : 0;
  return 'x';
}

describe('REPLY_SCHEMAS', () => {
  it.prop([fc.constantFrom(...commands), fc.anything()], { numRuns: 400 })(
    'never throw: any value is a typed reply that parses again to itself, or a refusal',
    (cmd, value) => {
      const schema = REPLY_SCHEMAS[cmd];
      const first = schema.safeParse(value);
      if (!first.success) return;
      const again = schema.safeParse(first.data);
      expect(again.success).toBe(true);
      expect(again.data).toEqual(first.data);
    },
  );

  it.prop([replyArb], { numRuns: 300 })(
    'read a valid reply as its fields, dropping unknown fields and taking null as absent',
    ({ cmd, clean, sent }) => {
      const parsed = REPLY_SCHEMAS[cmd].safeParse(sent);
      expect(parsed.success, JSON.stringify(parsed.error?.issues)).toBe(true);
      expect(parsed.data).toEqual(clean);
    },
  );

  it.prop([replyArb, fc.nat()], { numRuns: 300 })(
    'refuse a reply whose required field has the wrong type or is missing',
    ({ cmd, sent, required }, pick) => {
      const field = required[pick % required.length] ?? '';
      const schema = REPLY_SCHEMAS[cmd];
      expect(schema.safeParse({ ...sent, [field]: wrongType(sent[field]) }).success).toBe(false);
      const { [field]: _dropped, ...missing } = sent;
      expect(schema.safeParse(missing).success).toBe(false);
    },
  );
});
