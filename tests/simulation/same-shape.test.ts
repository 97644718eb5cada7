// One HAL, two bindings: every call of the call table, made on SimulationHAL and on PhysicalHAL
// (over the in-process mock robot: the wire binding over the mock link), answers in the same
// shape: the same result fields, nested to the leaf, the same value types, or the same error code.
// The simulated robot is given the V1 cube's parts (no camera, range sensors, IMU or speaker), so
// a part one world lacks is NOT_IMPLEMENTED in both.
import { PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import { SimulationHAL } from '@hal/simulation';
import { HAL_CALL_TABLE } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterAll, describe, expect, it } from 'vitest';

const TIME_SCALE = 50;

/** Arguments for each call of the table, in the order they are made. */
const ARGS: Record<string, unknown[]> = {
  moveForward: [5],
  moveBackward: [3],
  rotate: ['left', 30],
  drive: [120, 80, 300],
  moveTo: [0.05, 0.02, 0, 0.03],
  stop: [],
  getPose: [],
  captureFrame: [],
  getDistanceSensors: [],
  scan: ['quick'],
  getLineSensors: [],
  getIMU: [],
  setLED: [10, 20, 30, 'blink'],
  speak: ['hello', 'info'],
  playSound: ['beep'],
  log: ['a message', 'info'],
  getSafetyStatus: [],
  isEmergencyStopped: [],
  emergencyStop: ['shape check'],
  resetEmergencyStop: [],
};

/** A value's shape: object keys (sorted) with their shapes, an array's item shape, or a type. */
function shape(value: unknown): unknown {
  if (Array.isArray(value)) return value.length === 0 ? ['array'] : ['array', shape(value[0])];
  if (value !== null && typeof value === 'object') {
    return Object.fromEntries(
      Object.keys(value)
        .sort()
        .map((key) => [key, shape((value as Record<string, unknown>)[key])]),
    );
  }
  return value === null ? 'null' : typeof value;
}

/** Makes a call by its table entry; a rejection is returned as its error code. */
async function call(hal: HardwareAbstractionLayer, name: string): Promise<unknown> {
  const spec = HAL_CALL_TABLE.find((entry) => entry.name === name)!;
  const subsystem = hal[spec.subsystem] as unknown as Record<string, (...a: unknown[]) => unknown>;
  try {
    const answer = await subsystem[spec.method]!(...ARGS[name]!);
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
  it('have arguments here for every call of the table', () => {
    expect(Object.keys(ARGS).sort()).toEqual(HAL_CALL_TABLE.map((entry) => entry.name).sort());
  });

  it('answer every call of the table in the same shape, or fail it with the same code', async () => {
    await simulated.initialize();
    await physical.initialize();
    for (const name of Object.keys(ARGS)) {
      const sim = await call(simulated, name);
      const real = await call(physical, name);
      expect(sim, name).toEqual(real);
    }
  });

  it('give a pose that says whether the robot vouches for it, in both worlds', async () => {
    await simulated.initialize();
    await physical.initialize();
    expect((await simulated.locomotion.getPose()).confirmed).toBe(true);
    expect((await physical.locomotion.getPose()).confirmed).toBe(true);
  });
});
