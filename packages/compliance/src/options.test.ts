import { HalError } from '@hal/types';
import type { NatsConnection } from '@nats-io/transport-node';
import { describe, expect, it } from 'vitest';
import { resolveOptions } from './options.js';

const connection = {} as NatsConnection;

function errorOf(fn: () => unknown): HalError {
  try {
    fn();
  } catch (error) {
    if (error instanceof HalError) return error;
  }
  throw new Error('expected a HalError');
}

describe('resolveOptions', () => {
  it('fills in the defaults: small, short motions and 20 samples judged at p50', () => {
    expect(resolveOptions({ connection })).toMatchObject({
      samples: 20,
      judge: 'p50',
      driveSpeedMPerS: 0.02,
      turnRateRadPerS: 0.3,
      motionMs: 3000,
    });
  });

  it('refuses an mdns option that is not a boolean as INVALID_PARAMETER', () => {
    expect(
      errorOf(() => resolveOptions({ connection, mdns: 'yes' as unknown as boolean })),
    ).toMatchObject({
      code: 'INVALID_PARAMETER',
      message: '"mdns" must be true or false, got yes',
    });
    expect(resolveOptions({ connection })).toMatchObject({ mdns: false, mdnsTimeoutMs: 3000 });
  });

  it('refuses NaN and wrong types as INVALID_PARAMETER, naming the option', () => {
    expect(errorOf(() => resolveOptions({ connection, samples: Number.NaN }))).toMatchObject({
      code: 'INVALID_PARAMETER',
      message: expect.stringContaining('"samples"'),
    });
    expect(errorOf(() => resolveOptions({ connection, samples: 2.5 })).code).toBe(
      'INVALID_PARAMETER',
    );
    const judge = 'p75' as 'p50';
    expect(errorOf(() => resolveOptions({ connection, judge })).code).toBe('INVALID_PARAMETER');
  });

  it('refuses values out of range as RANGE_EXCEEDED, with the bounds', () => {
    const error = errorOf(() => resolveOptions({ connection, driveSpeedMPerS: 50 }));
    expect(error.code).toBe('RANGE_EXCEEDED');
    expect(error.details).toMatchObject({ parameter: 'driveSpeedMPerS', max: 10, value: 50 });
    expect(errorOf(() => resolveOptions({ connection, motionMs: 100 })).code).toBe(
      'RANGE_EXCEEDED',
    );
  });
});
