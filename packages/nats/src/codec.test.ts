import { HalError } from '@hal/types';
import { describe, expect, it } from 'vitest';
import {
  UNNAMED_SENDER,
  decodeArgs,
  decodeMessage,
  decodeSpecMessage,
  encodeArgs,
  encodeMessage,
} from './codec.js';
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

describe('spec messages', () => {
  const bytes = (value: unknown) => new TextEncoder().encode(JSON.stringify(value));

  it('take a bare spec payload as HAL v1 from an unnamed sender', () => {
    const message = decodeSpecMessage(
      bytes({ linear_vel_m_per_s: 0.02, angular_vel_rad_per_s: 0, duration_ms: 500 }),
      DifferentialCommandSchema,
    );
    expect(message.device_id).toBe(UNNAMED_SENDER);
    expect(message.hal_major).toBe(1);
    expect(message.payload.duration_ms).toBe(500);
  });

  it('still read an envelope as the envelope, naming its sender', () => {
    const data = encodeMessage('s', 'client-1', [], {
      linear_vel_m_per_s: 0,
      angular_vel_rad_per_s: 0,
    });
    expect(decodeSpecMessage(data, DifferentialCommandSchema).device_id).toBe('client-1');
  });

  it('refuse with MALFORMED what is neither an envelope nor a valid bare payload', () => {
    const refused = (value: unknown) => {
      try {
        decodeSpecMessage(bytes(value), DifferentialCommandSchema);
      } catch (error) {
        return error instanceof HalError ? `${error.code}: ${error.message}` : 'not a HalError';
      }
      return 'accepted';
    };
    expect(refused({ linear_vel_m_per_s: 'fast', angular_vel_rad_per_s: 0 })).toMatch(
      /^MALFORMED: neither a HAL envelope nor a bare payload/,
    );
    expect(refused({ duration_ms: 500 })).toMatch(/^MALFORMED/);
    expect(refused([1, 2])).toMatch(/^MALFORMED: not a HAL envelope/);
    // an envelope field makes it an envelope, held to the envelope's rules
    expect(refused({ hal_major: 1, linear_vel_m_per_s: 0, angular_vel_rad_per_s: 0 })).toMatch(
      /^MALFORMED: not a HAL envelope/,
    );
  });
});
