import { DifferentialStateSchema } from '@hal/nats';
import { describe, expect, it } from 'vitest';
import { inspect } from './inspect.js';

const bytes = (value: unknown) =>
  new TextEncoder().encode(typeof value === 'string' ? value : JSON.stringify(value));
const state = {
  left_vel_m_per_s: 0,
  right_vel_m_per_s: 0,
  linear_vel_m_per_s: 0,
  angular_vel_rad_per_s: 0,
  x_m: 0,
  y_m: 0,
  yaw_rad: 0,
  emergency_stopped: false,
  timestamp_ms: 1,
};
const envelope = (overrides: Record<string, unknown> = {}) => ({
  hal_major: 1,
  hal_minor: 0,
  schema: 'hal/motor/differential/state/1.0',
  device_id: 'cube-01',
  caps: ['motor.differential:v1.0'],
  ts: '2026-03-14T10:30:00.000Z',
  payload: state,
  ...overrides,
});

describe('inspect', () => {
  it("accepts the spec's envelope (ISO ts, unknown fields) with a valid payload", () => {
    const result = inspect(bytes({ ...envelope(), extra: 1 }), DifferentialStateSchema, 'cube-01');
    expect(result.issues).toEqual([]);
    expect(result.payload?.x_m).toBe(0);
  });

  it('names what is wrong: JSON, envelope, ts, hal_major, sender, capability strings, payload', () => {
    const issues = (data: Uint8Array) => inspect(data, DifferentialStateSchema, 'cube-01').issues;
    expect(issues(bytes('{"hal_major":'))).toEqual(['the message is not JSON']);
    expect(issues(bytes({ payload: state }))[0]).toMatch(/^not a HAL envelope/);
    expect(issues(bytes(envelope({ hal_major: 2 })))).toEqual(["hal_major is 2, the spec's is 1"]);
    expect(issues(bytes(envelope({ device_id: 'cube-02' })))).toEqual([
      'device_id is "cube-02", not the device "cube-01"',
    ]);
    expect(issues(bytes(envelope({ ts: 1710412200000 })))).toEqual([
      'ts is 1710412200000, not an ISO 8601 string as the spec writes it ("2024-03-14T10:30:00.000Z")',
    ]);
    expect(issues(bytes(envelope({ caps: ['motor'] })))).toEqual([
      'caps holds "motor", not a {domain}.{type}:v{major}.{minor} string',
    ]);
    expect(issues(bytes(envelope({ payload: { ...state, x_m: 'far' } })))).toEqual([
      'payload of "hal/motor/differential/state/1.0": x_m: Invalid input: expected number, received string',
    ]);
  });

  it("reads the spec's error shape as an error, not as a bad payload", () => {
    const error = { code: 'RANGE_EXCEEDED', message: 'too fast', details: { maximum: 2 } };
    const result = inspect(
      bytes(envelope({ payload: { error } })),
      DifferentialStateSchema,
      undefined,
    );
    expect(result.issues).toEqual([]);
    expect(result.error).toEqual(error);
    expect(result.payload).toBeUndefined();
  });
});
