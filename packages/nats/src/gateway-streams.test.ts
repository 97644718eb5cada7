import { SimulationHAL } from '@hal/simulation';
import type { DistanceSensors, HardwareAbstractionLayer, IMUReading } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { V1_ROBOT } from '@hal/types';
import {
  quaternionFromHeading,
  rangePerSensor,
  readDifferentialState,
  readImu,
  readRange,
} from './gateway-streams.js';

/** A simulated robot whose IMU reads as `imu`. */
function withImu(imu: IMUReading): HardwareAbstractionLayer {
  const hal = new SimulationHAL();
  hal.vision.getIMU = async () => imu;
  return hal;
}

const level: IMUReading = {
  acceleration: { x: 0, y: 0, z: 9.81 },
  gyroscope: { x: 0, y: 0, z: 0 },
  heading: Math.PI / 2,
  source: 'sensor',
};

describe('the IMU stream', () => {
  it('carries the orientation as the quaternion of the heading about z', () => {
    const q = quaternionFromHeading(Math.PI / 2);
    expect(q.w).toBeCloseTo(Math.SQRT1_2, 12);
    expect(q.z).toBeCloseTo(Math.SQRT1_2, 12);
    expect([q.x, q.y]).toEqual([0, 0]);
    const turned = quaternionFromHeading(-Math.PI);
    expect(Math.hypot(turned.w, turned.x, turned.y, turned.z)).toBeCloseTo(1, 12);
    expect(turned.z).toBeCloseTo(-1, 12);
  });

  it('leaves temperature and magnetic field out when the IMU has neither', async () => {
    const data = await readImu(withImu(level));
    expect(data).toBeDefined();
    expect(data).not.toHaveProperty('temperature_celsius');
    expect(data).not.toHaveProperty('mag_tesla');
    expect(data?.orientation_quaternion.z).toBeCloseTo(Math.SQRT1_2, 12);
  });

  it('passes temperature and magnetic field on when the IMU has them', async () => {
    const field = { x: 2.1e-5, y: -0.4e-5, z: 4.3e-5 };
    const data = await readImu(withImu({ ...level, temperature: 31.5, magneticField: field }));
    expect(data?.temperature_celsius).toBe(31.5);
    expect(data?.mag_tesla).toEqual(field);
  });
});

describe('the range streams', () => {
  const reading: DistanceSensors = {
    front: 0.4,
    left: 2,
    right: 1.25,
    limits: { minM: 0.02, maxM: 2, fieldOfViewDeg: 25 },
    source: 'simulation',
  };

  it("make one spec message per sensor, naming it, with the sensors' limits", () => {
    expect(rangePerSensor(reading)).toEqual([
      {
        sensor: 'front',
        distance_m: 0.4,
        min_range_m: 0.02,
        max_range_m: 2,
        fov_deg: 25,
        confidence: 1,
        source: 'simulation',
      },
      expect.objectContaining({ sensor: 'left', distance_m: 2, confidence: 0 }),
      expect.objectContaining({ sensor: 'right', distance_m: 1.25, confidence: 1 }),
    ]);
  });

  it('make no spec message when the limits of the sensors are unknown', () => {
    const { limits: _limits, ...unknown } = reading;
    expect(rangePerSensor(unknown)).toEqual([]);
  });

  it("read the simulated robot's five sensors in both forms", async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    try {
      const range = await readRange(hal);
      expect(range?.perSensor.map((m) => m.sensor)).toEqual([
        'front',
        'left',
        'right',
        'front_left',
        'front_right',
      ]);
      expect(range?.perSensor[0]?.distance_m).toBe(range?.summary.front_m);
      expect(range?.perSensor[0]?.max_range_m).toBe(2);
    } finally {
      await hal.cleanup();
    }
  });
});

describe('the state stream', () => {
  it('sends battery_volts and current_amps only when the robot measures them', async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    try {
      const unmeasured = await readDifferentialState(hal, V1_ROBOT);
      expect(unmeasured).not.toHaveProperty('battery_volts');
      expect(unmeasured).not.toHaveProperty('current_amps');
      const status = hal.safety.getSafetyStatus.bind(hal.safety);
      hal.safety.getSafetyStatus = () => ({
        ...status(),
        batteryVoltage: 7.4,
        batteryCurrent: 0.35,
      });
      const measured = await readDifferentialState(hal, V1_ROBOT);
      expect(measured).toMatchObject({ battery_volts: 7.4, current_amps: 0.35 });
    } finally {
      await hal.cleanup();
    }
  });
});
