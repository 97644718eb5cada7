import { fc, it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { fastEnvelope } from './envelope.js';
import { ReplyEnvelopeSchema } from './schemas.js';

// The hand-checked envelope against its definition, the zod schema: whatever the fast path
// accepts, the schema accepts, with an equal output (so the fast path is never less strict); and
// the fast path does take the common case, a successful reply with no nulls.

const uint32 = fc.integer({ min: 0, max: 4_294_967_295 });
/** A value for a field: often right, often wrong in every way JSON allows. */
const field = (right: fc.Arbitrary<unknown>) =>
  fc.oneof(
    { weight: 4, arbitrary: right },
    fc.constant(null),
    fc.integer({ min: -10, max: 10 }),
    fc.double(),
    fc.constant(4_294_967_296),
    fc.string(),
    fc.boolean(),
    fc.jsonValue(),
  );
const errorField = fc.oneof(
  fc.record(
    {
      code: fc.string(),
      message: fc.string(),
      details: fc.dictionary(fc.string(), fc.jsonValue()),
    },
    { requiredKeys: ['code', 'message'] },
  ),
  fc.jsonValue(),
);
const envelopeLike = fc.record(
  {
    seq: field(uint32),
    sid: field(uint32),
    ok: field(fc.boolean()),
    cmd: field(fc.string()),
    error: errorField,
    extra: fc.dictionary(fc.string(), fc.jsonValue()),
  },
  { requiredKeys: [] },
);
/** As a device sends it: through JSON, extra fields at the top level. */
const wire = envelopeLike.map(
  ({ extra, ...envelope }) => JSON.parse(JSON.stringify({ ...extra, ...envelope })) as unknown,
);

describe('fastEnvelope', () => {
  it.prop([fc.oneof(wire, fc.jsonValue())], { numRuns: 3000 })(
    'accepts only what the schema accepts, with the same output',
    (value) => {
      const fast = fastEnvelope(value);
      const schema = ReplyEnvelopeSchema.safeParse(value);
      if (fast !== undefined) {
        expect(schema.success).toBe(true);
        expect(fast).toStrictEqual(schema.data);
      }
    },
  );

  it.prop([
    fc.record(
      { seq: uint32, sid: uint32, ok: fc.boolean(), cmd: fc.string(), data: fc.jsonValue() },
      { requiredKeys: ['ok'] },
    ),
  ])('takes every successful reply without nulls in its envelope', (envelope) => {
    const value = JSON.parse(JSON.stringify(envelope)) as unknown;
    expect(fastEnvelope(value)).toBe(value);
  });

  it('leaves an error reply, a null and a __proto__ key to the schema', () => {
    expect(fastEnvelope({ ok: false, error: { code: 'X', message: 'm' } })).toBeUndefined();
    expect(fastEnvelope({ ok: true, seq: null })).toBeUndefined();
    expect(fastEnvelope(JSON.parse('{"ok":true,"__proto__":{"seq":1}}'))).toBeUndefined();
    expect(fastEnvelope([true])).toBeUndefined();
  });
});
