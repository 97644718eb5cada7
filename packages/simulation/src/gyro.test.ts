import { isHalError, normalizeAngle } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { SimulatedImu } from './gyro.js';
import type { ImuOptions } from './gyro.js';
import { SimulationHAL } from './hal/simulation-hal.js';
import { World } from './world.js';

const PERFECT: ImuOptions = { gyroBiasSigmaDegPerS: 0, gyroNoiseDensity: 0, accelNoiseSigma: 0 };
const DEG = Math.PI / 180;

function imuOn(options: ImuOptions, seed = 1) {
  const world = new World({ seed });
  const robot = world.addRobot({ start: { x: 0, y: 0, yaw: 0.3 } });
  const imu = new SimulatedImu(robot, options, () => Math.floor(world.random.next() * 2 ** 32));
  return { world, robot, imu };
}

describe('SimulatedImu', () => {
  it('with no errors reads gravity at rest and follows the true rotation while turning', () => {
    const { world, robot, imu } = imuOn(PERFECT);
    expect(imu.read(robot)).toMatchObject({
      acceleration: { x: 0, y: 0, z: 9.80665 },
      gyroscope: { x: 0, y: 0, z: 0 },
      source: 'simulation',
    });
    expect(imu.read(robot).heading).toBeCloseTo(0.3, 12);
    robot.drive(-1024, 1024);
    world.advance(3_000_000);
    const turning = imu.read(robot);
    expect(turning.gyroscope.z).toBeGreaterThan(0.9);
    expect(turning.heading).toBeCloseTo(robot.yaw, 12);
  });

  it('drifts at rest by its bias, and differs from the true yaw, by default', () => {
    const { world, robot, imu } = imuOn({});
    const start = imu.read(robot).heading;
    expect(Math.abs(imu.biasRadPerS)).toBeGreaterThan(0);
    world.advance(60_000_000);
    const later = imu.read(robot);
    expect(robot.yaw).toBeCloseTo(0.3, 12);
    expect(later.heading).not.toBe(robot.yaw);
    // a minute at rest: the bias's drift, give or take the noise's random walk (~0.08 degrees)
    const drift = normalizeAngle(later.heading - start);
    expect(drift).toBeCloseTo(imu.biasRadPerS * 60, 2);
    expect(later.gyroscope.z).not.toBe(0);
  });

  it('drifts with a bias alone exactly as bias times time', () => {
    const { world, robot, imu } = imuOn({ ...PERFECT, gyroBiasSigmaDegPerS: 1 });
    world.advance(10_000_000);
    const bias = imu.biasRadPerS;
    expect(Math.abs(bias)).toBeGreaterThan(0);
    expect(Math.abs(bias)).toBeLessThan(5 * DEG);
    expect(imu.read(robot).heading).toBeCloseTo(normalizeAngle(0.3 + bias * 10), 12);
  });

  it('repeats its errors with the same seed, and draws others with another', () => {
    const run = (seed: number) => {
      const { world, robot, imu } = imuOn({}, seed);
      robot.drive(-500, 500, 2000);
      world.advance(5_000_000);
      return [imu.read(robot), imu.read(robot)];
    };
    expect(run(5)).toEqual(run(5));
    expect(run(5)[1]?.heading).not.toBe(run(6)[1]?.heading);
    const fixed = (worldSeed: number) => {
      const { world, robot, imu } = imuOn({ seed: 42 }, worldSeed);
      world.advance(1_000_000);
      return imu.read(robot).heading;
    };
    expect(fixed(1)).toBe(fixed(2));
  });

  it('refuses a negative error with INVALID_PARAMETER naming it', () => {
    const world = new World();
    const robot = world.addRobot();
    let error: unknown;
    try {
      new SimulatedImu(robot, { gyroNoiseDensity: -1 }, () => 1);
    } catch (e) {
      error = e;
    }
    expect(isHalError(error) && error.code).toBe('INVALID_PARAMETER');
    expect(String(error)).toContain('"imu.gyroNoiseDensity"');
  });
});

describe('SimulationHAL#getIMU', () => {
  it('reads a heading that is neither the true yaw nor the odometry when the body drifts', async () => {
    const hal = new SimulationHAL({
      start: { x: 0, y: 0, yaw: 0 },
      bodyError: { odometryNoisePct: 5, seed: 3 },
    });
    await hal.initialize();
    try {
      expect(Math.abs((await hal.vision.getIMU()).heading)).toBeLessThan(1e-3);
      for (let i = 0; i < 4; i += 1) {
        expect((await hal.locomotion.rotate('left', 90)).success).toBe(true);
        expect((await hal.locomotion.moveForward(20)).success).toBe(true);
      }
      const imu = await hal.vision.getIMU();
      const pose = await hal.locomotion.getPose();
      expect(imu.source).toBe('simulation');
      expect(imu.heading).not.toBe(hal.robot.yaw);
      expect(Math.abs(normalizeAngle(imu.heading - hal.robot.yaw))).toBeGreaterThan(1e-4);
      expect(imu.heading).not.toBe(pose.rotation.yaw);
      // a gyro measures the body's turn: it stays nearer the truth than the odometry
      const off = (yaw: number) => Math.abs(normalizeAngle(yaw - hal.robot.yaw));
      expect(off(imu.heading)).toBeLessThan(off(pose.rotation.yaw));
    } finally {
      await hal.cleanup();
    }
  });

  it('with a perfect IMU reads the true heading, and without one the odometry heading', async () => {
    const world = new World();
    const perfect = new SimulationHAL({ world, imu: PERFECT });
    const none = new SimulationHAL({
      world,
      features: { imu: false },
      start: { x: 1, y: 1, yaw: 0 },
    });
    await perfect.initialize();
    await none.initialize();
    try {
      await perfect.locomotion.rotate('left', 30);
      expect((await perfect.vision.getIMU()).heading).toBeCloseTo(perfect.robot.yaw, 12);
      await none.locomotion.rotate('right', 30);
      const odometry = await none.vision.getIMU();
      expect(odometry.source).toBe('odometry');
      expect(odometry.heading).toBe(none.robot.reportedPose.yaw);
    } finally {
      await perfect.cleanup();
      await none.cleanup();
    }
  });
});
