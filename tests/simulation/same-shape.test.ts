// One HAL, two bindings: every call of the call table, made on SimulationHAL and on PhysicalHAL
// (over the in-process mock robot: the wire binding over the mock link), answers in the same
// shape: the same result fields, nested to the leaf, the same value types, or the same error code.
// The simulated robot is given the V1 cube's parts (no camera, range sensors, IMU or speaker), so
// a part one world lacks is NOT_IMPLEMENTED in both.
import { PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import { SimulationHAL } from '@hal/simulation';
import { HAL_CALL_TABLE } from '@hal/types';
import { CALL_SAMPLES } from '@hal/types/testing';
import type { CallName, HardwareAbstractionLayer } from '@hal/types';
import { afterAll, describe, expect, it } from 'vitest';

const TIME_SCALE = 50;

/** A value's shape: object keys (sorted) with their shapes, each item's shape, or a type. */
function shape(value: unknown): unknown {
  if (Array.isArray(value))
    return { array: [...new Set(value.map((v) => JSON.stringify(shape(v))))] };
  if (value !== null && typeof value === 'object') {
    return Object.fromEntries(
      Object.keys(value)
        .sort()
        .map((key) => [key, shape((value as Record<string, unknown>)[key])]),
    );
  }
  return value === null ? 'null' : typeof value;
}

/**
 * Where two shapes differ, by path: a field one side has and the other has not, or another type.
 * An empty array matches any array (how many items a list holds is the world's, not its shape).
 */
function differences(a: unknown, b: unknown, path = ''): string[] {
  const isArray = (v: unknown): v is { array: string[] } =>
    typeof v === 'object' && v !== null && 'array' in v;
  if (isArray(a) && isArray(b)) {
    if (a.array.length === 0 || b.array.length === 0) return [];
    return a.array.join() === b.array.join() ? [] : [`${path}[]: ${a.array} | ${b.array}`];
  }
  if (typeof a === 'object' && a !== null && typeof b === 'object' && b !== null) {
    const keys = [...new Set([...Object.keys(a), ...Object.keys(b)])].sort();
    return keys.flatMap((key) => {
      const x = (a as Record<string, unknown>)[key];
      const y = (b as Record<string, unknown>)[key];
      if (x === undefined || y === undefined) return [`${path}.${key}: only in one world`];
      return differences(x, y, `${path}.${key}`);
    });
  }
  return JSON.stringify(a) === JSON.stringify(b)
    ? []
    : [`${path}: ${JSON.stringify(a)} | ${JSON.stringify(b)}`];
}

/** Makes a call by its table entry; a rejection is returned as its error code. */
async function call(hal: HardwareAbstractionLayer, name: string): Promise<unknown> {
  const spec = HAL_CALL_TABLE.find((entry) => entry.name === name)!;
  const subsystem = hal[spec.subsystem] as unknown as Record<string, (...a: unknown[]) => unknown>;
  try {
    const answer = await subsystem[spec.method]!(...CALL_SAMPLES[spec.name as CallName]);
    if (spec.kind === 'motion' || spec.kind === 'result') {
      const result = answer as { success: boolean; code?: string; data?: unknown };
      return result.success ? { data: shape(result.data) } : { code: result.code };
    }
    return { value: shape(answer) };
  } catch (error) {
    return { code: (error as { code?: string }).code ?? String(error) };
  }
}

const simulated = new SimulationHAL({
  features: { camera: false, rangeSensors: false, imu: false, speaker: false },
});
const physical = new PhysicalHAL(
  { mode: 'physical', deviceId: 'cube-shape' },
  {
    transport: new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 }).transport(),
    timeScale: TIME_SCALE,
  },
);

afterAll(async () => {
  await simulated.cleanup();
  await physical.cleanup();
});

describe('SimulationHAL and PhysicalHAL', () => {
  it('answer every call of the table in the same shape, or fail it with the same code', async () => {
    await simulated.initialize();
    await physical.initialize();
    // in the table's order: the e-stop is followed by its reset, and motions come before both
    for (const { name } of HAL_CALL_TABLE) {
      const sim = await call(simulated, name);
      const real = await call(physical, name);
      expect(differences(sim, real), name).toEqual([]);
    }
  });

  it('give a pose that says whether the robot vouches for it, in both worlds', async () => {
    await simulated.initialize();
    await physical.initialize();
    expect((await simulated.locomotion.getPose()).confirmed).toBe(true);
    expect((await physical.locomotion.getPose()).confirmed).toBe(true);
  });
});
