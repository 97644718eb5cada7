import { describe, expect, it } from 'vitest';
import { deviceOfflineError, HalError, isHalError, toHalError } from './errors.js';
import { failureResult, HALToolResultSchema, successResult } from './result.js';
import { HALConfigSchema, robotConfig, V1_ROBOT } from './robot-config.js';
import { V1_CALL_SCHEMAS } from './schemas/calls.js';
import { z } from 'zod';

describe('HALToolResult', () => {
  it('builds successes and failures that satisfy the schema', () => {
    expect(HALToolResultSchema.parse(successResult('physical', 5, { a: 1 }, 2))).toEqual({
      success: true,
      timestamp: 5,
      mode: 'physical',
      data: { a: 1 },
      executionTime: 2,
    });
    const failed = failureResult(
      'hybrid',
      6,
      new HalError('TIMEOUT', 'late', { details: { ms: 1 } }),
    );
    expect(HALToolResultSchema.parse(failed)).toMatchObject({
      success: false,
      code: 'TIMEOUT',
      details: { ms: 1 },
    });
  });

  it('rejects a failure without a code', () => {
    expect(
      HALToolResultSchema.safeParse({
        success: false,
        error: 'x',
        timestamp: 1,
        mode: 'simulation',
      }).success,
    ).toBe(false);
  });
});

describe('HalError', () => {
  it('carries a literal code, details and a cause', () => {
    const cause = new Error('socket closed');
    const error = new HalError('NOT_CONNECTED', 'robot unreachable', {
      cause,
      details: { host: '1.2.3.4' },
    });
    expect(error.name).toBe('HalError');
    expect(error.cause).toBe(cause);
    expect(isHalError(error)).toBe(true);
    expect(isHalError(new Error('x'))).toBe(false);
    expect(toHalError(error)).toBe(error);
    expect(toHalError('text')).toMatchObject({ code: 'HARDWARE_ERROR', message: 'text' });
  });

  it('says a device is offline with NOT_CONNECTED and details that name it, whatever else it adds', () => {
    const cause = new Error('no responders');
    const error = deviceOfflineError(
      'cube-01',
      'silent for 3000 ms',
      { subject: 'x', offline: 0 },
      cause,
    );
    expect(error).toMatchObject({
      code: 'NOT_CONNECTED',
      message: 'device "cube-01" is offline: silent for 3000 ms',
      details: { subject: 'x', device: 'cube-01', offline: true },
    });
    expect(error.cause).toBe(cause);
    expect(failureResult('physical', 1, deviceOfflineError('cube-02'))).toMatchObject({
      code: 'NOT_CONNECTED',
      details: { device: 'cube-02', offline: true },
    });
  });
});

describe('robot configuration', () => {
  it('defaults to the V1 robot figures', () => {
    expect(V1_ROBOT).toMatchObject({
      stepsPerRevolution: 4096,
      wheelDiameterCm: 6,
      wheelBaseCm: 10,
      maxSpeedStepsPerS: 1024,
      accelerationStepsPerS2: 512,
      maxStepsPerCommand: 40960,
      hostTimeoutMs: 2000,
    });
  });

  it('refuses limits the firmware would refuse', () => {
    expect(() => robotConfig({ maxSpeedStepsPerS: 4096 })).toThrow();
    expect(() => robotConfig({ hostTimeoutMs: 100 })).toThrow();
    expect(robotConfig({ stepsPerRevolution: 4076 }).stepsPerRevolution).toBe(4076);
  });

  it('accepts a seed-style HAL config and refuses a device id with spaces', () => {
    expect(
      HALConfigSchema.parse({
        mode: 'physical',
        deviceId: 'cube-01',
        connection: { type: 'wifi', host: '10.0.0.5' },
      }).connection?.host,
    ).toBe('10.0.0.5');
    expect(HALConfigSchema.safeParse({ mode: 'physical', deviceId: 'cube 01' }).success).toBe(
      false,
    );
  });
});

describe('call schemas', () => {
  it('describe every parameter with its unit or range (they become LLM tool descriptions)', () => {
    for (const [call, schema] of Object.entries(V1_CALL_SCHEMAS)) {
      expect(schema.description, call).toBeTruthy();
      const json = z.toJSONSchema(schema) as {
        properties?: Record<string, { description?: string }>;
      };
      for (const [name, property] of Object.entries(json.properties ?? {})) {
        expect(property.description, `${call}.${name}`).toBeTruthy();
      }
    }
    expect(V1_CALL_SCHEMAS.moveForward.shape.distanceCm.description).toMatch(/cm.*at most 188\.\d/);
  });
});
