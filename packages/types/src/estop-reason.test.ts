import { describe, expect, it } from 'vitest';
import {
  DEFAULT_ESTOP_REASON,
  ESTOP_REASON_MAX_BYTES,
  sanitizeEstopReason,
} from './estop-reason.js';
import { V1_CALL_SCHEMAS } from './schemas/calls.js';

const bytes = (text: string) => new TextEncoder().encode(text).length;

describe('sanitizeEstopReason', () => {
  it('keeps a short printable reason as it is', () => {
    expect(sanitizeEstopReason('bumper hit')).toBe('bumper hit');
    expect(sanitizeEstopReason('stop ✋ now')).toBe('stop ✋ now');
  });

  it('gives the default reason for undefined, null, objects, symbols and blank text', () => {
    for (const value of [undefined, null, {}, [], Symbol('x'), () => 1, '', '   ', '\u0000\n']) {
      expect(sanitizeEstopReason(value)).toBe(DEFAULT_ESTOP_REASON);
    }
  });

  it('turns numbers, booleans, bigints and errors into their text', () => {
    expect(sanitizeEstopReason(42)).toBe('42');
    expect(sanitizeEstopReason(Number.NaN)).toBe('NaN');
    expect(sanitizeEstopReason(true)).toBe('true');
    expect(sanitizeEstopReason(10n)).toBe('10');
    expect(sanitizeEstopReason(new Error('cliff'))).toBe('cliff');
  });

  it('replaces every run of control characters with one space and trims the ends', () => {
    expect(sanitizeEstopReason('\tline one\r\n\u0007line two\u009f\u007f')).toBe(
      'line one line two',
    );
  });

  it('replaces lone surrogates and keeps valid pairs', () => {
    expect(sanitizeEstopReason('a\ud800b')).toBe('a\ufffdb');
    expect(sanitizeEstopReason('a\udc00')).toBe('a\ufffd');
    expect(sanitizeEstopReason('🤖')).toBe('🤖');
  });

  it('cuts to the byte limit without splitting a character', () => {
    expect(sanitizeEstopReason('x'.repeat(201))).toBe('x'.repeat(ESTOP_REASON_MAX_BYTES));
    const emoji = sanitizeEstopReason('🤖'.repeat(40));
    expect(bytes(emoji)).toBeLessThanOrEqual(ESTOP_REASON_MAX_BYTES);
    expect(emoji).toBe('🤖'.repeat(Math.floor(ESTOP_REASON_MAX_BYTES / 4)));
    expect(sanitizeEstopReason('é'.repeat(100))).toBe('é'.repeat(31));
  });

  it('stays short after JSON escaping, whatever the input', () => {
    const worst = sanitizeEstopReason('"\\'.repeat(500) + '\u0001'.repeat(200));
    expect(bytes(JSON.stringify(worst))).toBeLessThanOrEqual(2 * ESTOP_REASON_MAX_BYTES + 2);
    expect(sanitizeEstopReason('\u0001'.repeat(200))).toBe(DEFAULT_ESTOP_REASON);
  });

  it('is what the emergencyStop call schema stores, for any argument', () => {
    const schema = V1_CALL_SCHEMAS.emergencyStop;
    for (const reason of ['x'.repeat(201), 42, undefined, {}, '\u0000a\ud800']) {
      expect(schema.parse({ reason })).toEqual({ reason: sanitizeEstopReason(reason) });
    }
    expect(schema.parse({})).toEqual({ reason: DEFAULT_ESTOP_REASON });
  });
});
