import { fc, it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { fastReply } from './reply-fast.js';
import { MOVE_OUTCOMES, REPLY_SCHEMAS } from './schemas.js';
import type { Command } from './schemas.js';
import { byte, finite, int, motionReplyFields, uint32 } from './reply-fields.fixture.js';

// The hand-checked reply data against its definition, the command's zod schema: whatever the
// fast path accepts, the schema accepts, with an equal output (so the fast path is never less
// strict); and the fast path does take the common case, a well-formed reply without nulls.

/** A value for a field: often right, often wrong in every way JSON (and a caller) allows. */
const field = (right: fc.Arbitrary<unknown>) =>
  fc.oneof(
    { weight: 6, arbitrary: right },
    fc.constant(null),
    fc.constant(undefined),
    fc.integer({ min: -300, max: 300 }),
    fc.double(),
    fc.constantFrom(2 ** 53, 4_294_967_296, -1, 256, 0.5),
    fc.string(),
    fc.boolean(),
    fc.jsonValue(),
  );
const extra = fc.dictionary(fc.string(), fc.jsonValue(), { maxKeys: 3 });

/** An object of `fields`, each maybe wrong or absent, with unknown extra fields. */
const objectOf = (fields: Record<string, fc.Arbitrary<unknown>>, required: boolean) =>
  fc
    .tuple(
      fc.record(Object.fromEntries(Object.entries(fields).map(([k, a]) => [k, field(a)])), {
        requiredKeys: required ? Object.keys(fields) : [],
      }),
      extra,
    )
    .map(([known, unknown]) => ({ ...unknown, ...known }));
/** The same object, each field always right: what a robot sends. */
const wellFormed = (fields: Record<string, fc.Arbitrary<unknown>>) => fc.record(fields);

const ledFields = { r: byte, g: byte, b: byte, pattern: fc.string() };
const motionFields = { move_id: uint32, ...motionReplyFields };
const statusFields = (make: typeof objectOf | typeof wellFormed, required = true) => ({
  x_cm: finite,
  y_cm: finite,
  heading_rad: finite,
  left_steps: int,
  right_steps: int,
  running: fc.boolean(),
  move_id: uint32,
  move_outcome: fc.constantFrom(...MOVE_OUTCOMES),
  move_left_steps: int,
  move_right_steps: int,
  left_sps: finite,
  right_sps: finite,
  uptime_ms: int,
  safety: make(
    {
      estop: fc.boolean(),
      estop_reason: fc.string(),
      trips: int,
      last_trip: make({ reason: fc.string(), detail: fc.string(), uptime_ms: int }, required),
      host_timeout_ms: int,
      ms_since_host: int,
      coils_on: fc.boolean(),
    },
    required,
  ),
  led: make(ledFields, required),
});

/** Replies to each fast command: fuzzed, then through JSON as a device sends them. */
const cases: [Command, fc.Arbitrary<unknown>, fc.Arbitrary<unknown>][] = [
  [
    'set_led',
    objectOf({ led: objectOf(ledFields, true) }, false),
    wellFormed({ led: wellFormed(ledFields) }),
  ],
  [
    'heartbeat',
    objectOf({ uptime_ms: int, running: fc.boolean(), estop: fc.boolean() }, false),
    wellFormed({ uptime_ms: int, running: fc.boolean(), estop: fc.boolean() }),
  ],
  ['drive', objectOf(motionFields, false), fc.record(motionFields, { requiredKeys: ['move_id'] })],
  [
    'move_steps',
    objectOf(motionFields, false),
    fc.record(motionFields, { requiredKeys: ['move_id'] }),
  ],
  ['get_status', objectOf(statusFields(objectOf), false), wellFormed(statusFields(wellFormed))],
];
const viaJson = (value: unknown) => JSON.parse(JSON.stringify(value ?? null)) as unknown;

describe('fastReply', () => {
  for (const [cmd, fuzzed, good] of cases) {
    it.prop([fc.oneof(fuzzed, fuzzed.map(viaJson), fc.jsonValue())], { numRuns: 1500 })(
      `accepts a ${cmd} reply only when the schema does, with the same output`,
      (value) => {
        const fast = fastReply(cmd, value);
        const schema = REPLY_SCHEMAS[cmd].safeParse(value);
        if (fast !== undefined) {
          expect(schema.success).toBe(true);
          expect(fast).toStrictEqual(schema.data);
        }
      },
    );

    it.prop([good.map(viaJson)], { numRuns: 300 })(
      `takes every well-formed ${cmd} reply without nulls`,
      (value) => {
        expect(fastReply(cmd, value)).toStrictEqual(REPLY_SCHEMAS[cmd].parse(value));
      },
    );
  }

  it('leaves a null, a wrong type and the commands it does not know to the schema', () => {
    const led = { r: 1, g: 2, b: 3, pattern: 'solid' };
    expect(fastReply('set_led', { led })).toStrictEqual({ led });
    expect(fastReply('set_led', { led: { ...led, r: 256 } })).toBeUndefined();
    expect(fastReply('drive', { move_id: 3, speed: null })).toBeUndefined();
    expect(fastReply('set_led', { led: { ...led, pattern: 7 } })).toBeUndefined();
    expect(fastReply('hello', { sid: 1 })).toBeUndefined();
  });
});
