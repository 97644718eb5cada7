import { HalError } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { MockRobot } from '../mock/mock-robot.js';
import { sendCalibration } from './calibration.js';
import type { WheelCalibration } from './calibration.js';
import { PhysicalHAL } from './physical-hal.js';
import type { PhysicalHALOptions } from './options.js';

const TIME_SCALE = 50;
const MEASURED: WheelCalibration = { wheelDiameterCm: 6.6, wheelBaseCm: 10.4 };

function rig(options: PhysicalHALOptions = {}): { robot: MockRobot; hal: PhysicalHAL } {
  const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000, deviceId: 'cube-7' });
  const hal = new PhysicalHAL(
    { mode: 'physical', deviceId: 'cube-7' },
    { transport: robot.transport(), timeScale: TIME_SCALE, reconnectIntervalMs: 10, ...options },
  );
  return { robot, hal };
}

const commands = (robot: MockRobot) => robot.requests.map((r) => r['cmd']);
const setConfigs = (robot: MockRobot) => robot.requests.filter((r) => r['cmd'] === 'set_config');

describe('PhysicalHAL calibration', () => {
  it('sends the calibration of the device its hello names with set_config, after hello and the status', async () => {
    const asked: string[] = [];
    const { robot, hal } = rig({
      calibration: (deviceId) => {
        asked.push(deviceId);
        return MEASURED;
      },
    });
    await hal.initialize();
    expect(asked).toEqual(['cube-7']);
    expect(commands(robot).slice(0, 3)).toEqual(['hello', 'get_status', 'set_config']);
    expect(setConfigs(robot)[0]).toMatchObject({ wheel_diameter_cm: 6.6, wheel_base_cm: 10.4 });
    expect(hal.robotConfig).toMatchObject({ wheelDiameterCm: 6.6, wheelBaseCm: 10.4 });
    await hal.cleanup();
  });

  it('dead-reckons with the calibrated wheels: 10 cm is 1975 steps of a 6.6 cm wheel', async () => {
    const { robot, hal } = rig({ calibration: () => MEASURED });
    await hal.initialize();
    const result = await hal.locomotion.moveForward(10);
    expect(result.success, JSON.stringify(result)).toBe(true);
    expect(robot.position).toEqual({ left: 1975, right: 1975 });
    const pose = await hal.locomotion.getPose();
    expect(pose.position.x).toBeCloseTo(0.1, 3);
    await hal.cleanup();
  });

  it('sends the calibration again after the robot restarts and the HAL says hello again', async () => {
    const { robot, hal } = rig({ calibration: () => MEASURED });
    await hal.initialize();
    robot.restart();
    expect((await hal.locomotion.moveForward(1)).code).toBe('NOT_CONNECTED');
    await expect.poll(() => setConfigs(robot).length, { timeout: 5000 }).toBe(2);
    const hellos = commands(robot).filter((c) => c === 'hello').length;
    expect(hellos).toBe(2);
    await hal.cleanup();
  });

  it('latches a restarted robot e-stopped by the host before it sends the calibration again', async () => {
    const { robot, hal } = rig({ calibration: () => MEASURED });
    await hal.initialize();
    expect((await hal.safety.emergencyStop('operator')).success).toBe(true);
    robot.restart();
    await expect.poll(() => setConfigs(robot).length, { timeout: 5000 }).toBe(2);
    const sinceHello = commands(robot).slice(commands(robot).lastIndexOf('hello'));
    expect(sinceHello.indexOf('estop')).toBeGreaterThan(0);
    expect(sinceHello.indexOf('estop')).toBeLessThan(sinceHello.indexOf('set_config'));
    expect(robot.estopped).toBe(true);
    await hal.cleanup();
  });

  it('sends nothing when the source has no calibration for the robot', async () => {
    const { robot, hal } = rig({ calibration: () => undefined });
    await hal.initialize();
    expect(setConfigs(robot)).toHaveLength(0);
    expect(hal.robotConfig.wheelDiameterCm).toBe(6);
    await hal.cleanup();
  });

  it('fails initialize with RANGE_EXCEEDED naming the field and its range, sending nothing', async () => {
    const { robot, hal } = rig({ calibration: () => ({ wheelDiameterCm: 60, wheelBaseCm: 10 }) });
    const failed = hal.initialize();
    await expect(failed).rejects.toMatchObject({
      code: 'RANGE_EXCEEDED',
      message: expect.stringMatching(
        /"wheel_diameter_cm" must be a number in 0\.5\.\.50 cm, got 60/,
      ),
    });
    expect(setConfigs(robot)).toHaveLength(0);
  });

  it('applies a calibration now and keeps sending it after later hellos', async () => {
    const { robot, hal } = rig();
    await hal.initialize();
    const config = await hal.applyCalibration({ wheelDiameterCm: 5.8, wheelBaseCm: 9.7 });
    expect(config).toMatchObject({ wheelDiameterCm: 5.8, wheelBaseCm: 9.7 });
    robot.restart();
    await expect.poll(() => setConfigs(robot).length, { timeout: 5000 }).toBe(2);
    expect(setConfigs(robot)[1]).toMatchObject({ wheel_diameter_cm: 5.8, wheel_base_cm: 9.7 });
    await expect(
      hal.applyCalibration({ wheelDiameterCm: Number.NaN, wheelBaseCm: 9 }),
    ).rejects.toMatchObject({ code: 'RANGE_EXCEEDED', message: expect.stringMatching(/got NaN/) });
    await hal.cleanup();
  });
});

describe('sendCalibration', () => {
  const config = {
    wheel_diameter_cm: 6.6,
    wheel_base_cm: 10.4,
    steps_per_revolution: 4096,
    max_speed_steps_per_s: 1024,
    acceleration_steps_per_s2: 512,
    host_timeout_ms: 2000,
  };

  it("passes a refusal on with the robot's code, the values sent and the robot's reason", async () => {
    const refused = new HalError(
      'RANGE_EXCEEDED',
      'the robot refused "set_config": wheel_base_cm must be 1..100 cm',
    );
    await expect(
      sendCalibration(() => Promise.reject(refused), MEASURED, 'cube-7'),
    ).rejects.toMatchObject({
      code: 'RANGE_EXCEEDED',
      message:
        'robot cube-7 did not take its calibration (wheel_diameter_cm=6.6, wheel_base_cm=10.4): ' +
        'the robot refused "set_config": wheel_base_cm must be 1..100 cm',
    });
  });

  it('is a HARDWARE_ERROR naming the field when the robot reports other values than were sent', async () => {
    const reply = { config: { ...config, wheel_base_cm: 10 } };
    await expect(
      sendCalibration(() => Promise.resolve(reply), MEASURED, 'cube-7'),
    ).rejects.toMatchObject({
      code: 'HARDWARE_ERROR',
      message: 'robot cube-7 reports wheel_base_cm=10 after set_config wheel_base_cm=10.4',
    });
  });

  it('resolves the configuration the robot reports when it took the values', async () => {
    const reply = { config: { ...config, wheel_diameter_cm: 6.600000000001 } };
    expect(await sendCalibration(() => Promise.resolve(reply), MEASURED, 'cube-7')).toEqual(
      reply.config,
    );
  });
});
