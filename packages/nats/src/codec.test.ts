import { HalError } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { decodeArgs, decodeMessage, encodeArgs, encodeMessage } from './codec.js';
import { DifferentialCommandSchema } from './messages.js';

describe('call arguments', () => {
  it('keep NaN, infinities and undefined across JSON, and drop trailing undefined', () => {
    const sent = encodeArgs([Number.NaN, Infinity, undefined, -Infinity, 'x', undefined]);
    const received = decodeArgs(JSON.parse(JSON.stringify(sent)) as unknown[]);
    expect(received).toEqual([Number.NaN, Infinity, undefined, -Infinity, 'x']);
  });
});

describe('messages', () => {
  it('round-trip in the envelope, with the sender as device_id and unknown fields kept', () => {
    const data = encodeMessage('s', 'client-1', [], {
      linear_vel_m_per_s: 0.01,
      angular_vel_rad_per_s: 0,
      extra: 1,
    });
    const message = decodeMessage(data, DifferentialCommandSchema);
    expect(message.device_id).toBe('client-1');
    expect(message.payload).toMatchObject({ linear_vel_m_per_s: 0.01, extra: 1 });
  });

  it('refuses bytes that are not JSON, or a payload without its fields, with MALFORMED', () => {
    expect(() => decodeMessage(new Uint8Array([0xff, 0x00]), DifferentialCommandSchema)).toThrow(
      HalError,
    );
    const data = encodeMessage('s', 'client-1', [], { linear_vel_m_per_s: 'fast' });
    expect(() => decodeMessage(data, DifferentialCommandSchema)).toThrow(
      /linear_vel_m_per_s|expected number/,
    );
  });
});
