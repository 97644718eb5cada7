import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { MAX_RECORDED_STRING, jsonSafe, jsonSafeCopy } from './json-safe.js';

/** Values as calls take and answer them, and the ones a record must not take as they are. */
const callValue = fc.letrec((tie) => ({
  value: fc.oneof(
    { depthSize: 'small' },
    fc.string({ maxLength: 8 }),
    fc.string({ minLength: MAX_RECORDED_STRING - 2, maxLength: MAX_RECORDED_STRING + 2 }),
    fc.double(),
    fc.integer(),
    fc.bigInt(),
    fc.boolean(),
    fc.constant(null),
    fc.constant(undefined),
    fc.constant(() => 1),
    fc.date({ noInvalidDate: true }),
    fc.string().map((message) => new Error(message)),
    fc.array(tie('value'), { maxLength: 4 }),
    fc.dictionary(fc.string({ maxLength: 4 }), tie('value'), { maxKeys: 4 }),
  ),
})).value;

describe('jsonSafe', () => {
  it('makes the same JSON as the copy, for any value', () => {
    fc.assert(
      fc.property(callValue, (value) => {
        expect(JSON.stringify(jsonSafe(value))).toBe(JSON.stringify(jsonSafeCopy(value)));
      }),
      { numRuns: 2000 },
    );
  });

  it('hands a value that is already JSON-safe back as it is', () => {
    const result = { success: true, mode: 'physical', pose: { x: 1, y: [2, 3] }, note: undefined };
    expect(jsonSafe(result)).toBe(result);
    expect(jsonSafe([1, 'a', null])).toEqual([1, 'a', null]);
  });

  it('copies what JSON cannot take as it is', () => {
    const cyclic: Record<string, unknown> = { a: 1 };
    cyclic['self'] = cyclic;
    expect(jsonSafe(cyclic)).toEqual({ a: 1, self: '[circular]' });
    expect(jsonSafe({ n: Number.NaN, big: 10n })).toEqual({ n: 'NaN', big: '10' });
    expect(jsonSafe('x'.repeat(600))).toBe(`${'x'.repeat(64)}... (600 characters)`);
    expect(jsonSafe(new Error('stalled'))).toEqual({ name: 'Error', message: 'stalled' });
    expect(jsonSafe(undefined)).toBeUndefined();
    // deeper than the check goes: copied, the same text
    let deep: unknown = 1;
    for (let i = 0; i < 40; i++) deep = [deep];
    expect(JSON.stringify(jsonSafe(deep))).toBe(JSON.stringify(deep));
  });
});
