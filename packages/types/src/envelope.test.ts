import { describe, expect, it } from 'vitest';
import { z } from 'zod';
import {
  buildSubject,
  EnvelopeSchema,
  envelopeTimeMs,
  HalErrorPayloadSchema,
  makeEnvelope,
  parseEnvelope,
  parseSubject,
} from './envelope.js';
import { HalError } from './errors.js';

const PoseMessage = z.looseObject({ x_m: z.number(), y_m: z.number(), yaw_rad: z.number() });

describe('envelope', () => {
  it('wraps and parses a payload, ignoring unknown fields at both levels', () => {
    const envelope = makeEnvelope(
      { schema: 'hal.locomotion.pose', device_id: 'cube-01', caps: ['safety.estop:v1.0'], ts: 42 },
      { x_m: 1, y_m: 2, yaw_rad: 0 },
    );
    expect(EnvelopeSchema.parse(envelope)).toMatchObject({ hal_major: 1, hal_minor: 0, ts: 42 });
    const wire = JSON.parse(
      JSON.stringify({ ...envelope, extra: true, payload: { ...envelope.payload, note: 'x' } }),
    );
    const parsed = parseEnvelope(wire, PoseMessage);
    expect(parsed.payload.x_m).toBe(1);
    expect(parsed.device_id).toBe('cube-01');
  });

  it('writes ts as an ISO 8601 string, as the spec does, and reads both forms back as a time', () => {
    const before = Date.now();
    const envelope = makeEnvelope({ schema: 's', device_id: 'd' }, {});
    expect(envelope.ts).toMatch(/^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$/);
    expect(envelopeTimeMs(envelope)).toBeGreaterThanOrEqual(before);
    expect(envelopeTimeMs({ ts: '2024-03-14T10:30:00.000Z' })).toBe(1710412200000);
    expect(envelopeTimeMs({ ts: 1710412200000 })).toBe(1710412200000);
  });

  it('refuses a newer major version, a bad payload and a non-envelope with MALFORMED', () => {
    const envelope = makeEnvelope({ schema: 's', device_id: 'd' }, { x_m: 1, y_m: 2, yaw_rad: 0 });
    expect(() => parseEnvelope({ ...envelope, hal_major: 2 }, PoseMessage)).toThrow(/hal_major 2/);
    expect(() => parseEnvelope({ ...envelope, payload: { x_m: 'a' } }, PoseMessage)).toThrow(
      HalError,
    );
    expect(() => parseEnvelope('hello', PoseMessage)).toThrow(/not a HAL envelope/);
  });

  it('refuses a device id that cannot be a subject token', () => {
    expect(() => makeEnvelope({ schema: 's', device_id: 'cube 01' }, {})).toThrow(/device_id/);
  });

  it('has the standard error shape, tolerant of unknown fields', () => {
    expect(
      HalErrorPayloadSchema.parse({ code: 'TIMEOUT', message: 'late', retry_ms: 10 }),
    ).toMatchObject({
      code: 'TIMEOUT',
      retry_ms: 10,
    });
    expect(HalErrorPayloadSchema.safeParse({ message: 'no code' }).success).toBe(false);
  });
});

describe('subjects', () => {
  it('builds the spec subjects as written for the default device, and dev.{device} ones for a fleet', () => {
    expect(buildSubject({ domain: 'motor', type: 'differential', action: 'cmd' })).toBe(
      'hal.v1.motor.differential.cmd',
    );
    expect(buildSubject({ device: 'cube-01', domain: 'sensor', type: 'imu', action: 'data' })).toBe(
      'hal.v1.dev.cube-01.sensor.imu.data',
    );
    expect(parseSubject('hal.v1.system.health.req')).toEqual({
      domain: 'system',
      type: 'health',
      action: 'req',
      major: 1,
    });
    expect(parseSubject('hal.v1.dev.cube-01.safety.estop.cmd')).toEqual({
      device: 'cube-01',
      domain: 'safety',
      type: 'estop',
      action: 'cmd',
      major: 1,
    });
  });

  it('builds wildcard subscriptions only when asked, with ">" last', () => {
    expect(
      buildSubject(
        { device: '*', domain: 'sensor', type: 'imu', action: 'data' },
        { wildcards: true },
      ),
    ).toBe('hal.v1.dev.*.sensor.imu.data');
    expect(() =>
      buildSubject({ device: '*', domain: 'safety', type: 'estop', action: 'cmd' }),
    ).toThrow(HalError);
    expect(() =>
      buildSubject({ device: 'a', domain: '>', type: 'estop', action: 'set' }, { wildcards: true }),
    ).toThrow(/may only be last/);
    expect(() => buildSubject({ domain: 'dev', type: 'x', action: 'y' })).toThrow(
      /may not be "dev"/,
    );
  });

  it("accepts the spec's ISO 8601 ts as well as ms since the epoch, and nothing else", () => {
    const base = { hal_major: 1, hal_minor: 0, schema: 's', device_id: 'd', caps: [], payload: {} };
    expect(EnvelopeSchema.safeParse({ ...base, ts: '2024-03-14T10:30:00.000Z' }).success).toBe(
      true,
    );
    expect(EnvelopeSchema.safeParse({ ...base, ts: 1710412200000 }).success).toBe(true);
    expect(EnvelopeSchema.safeParse({ ...base, ts: 'yesterday' }).success).toBe(false);
  });

  it('refuses subjects that are not ours', () => {
    expect(() => parseSubject('hal.cube.locomotion.pose.update')).toThrow(HalError);
    expect(() => parseSubject('hal.v1.dev.cube 01.locomotion.pose.update')).toThrow(HalError);
    expect(() => parseSubject('hal.v1.cube-01.locomotion.pose.update')).toThrow(HalError);
  });
});
