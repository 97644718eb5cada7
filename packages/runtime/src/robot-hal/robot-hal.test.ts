import { stepsPerCm, V1_ROBOT } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { FakePort } from './fake-port.fixture.js';
import { powerToStepsPerS } from './locomotion.js';
import { RobotHAL } from './robot-hal.js';

async function ready(port = new FakePort()): Promise<{ hal: RobotHAL<FakePort>; port: FakePort }> {
  const hal = new RobotHAL(port);
  await hal.initialize();
  return { hal, port };
}

describe('RobotHAL', () => {
  describe('lifecycle', () => {
    it('opens the port once however many callers wait, and refuses calls before it', async () => {
      const port = new FakePort();
      const hal = new RobotHAL(port);
      const early = await hal.locomotion.moveForward(5);
      expect(early.code).toBe('NOT_READY');
      expect(port.commands).toEqual([]);
      await Promise.all([hal.initialize(), hal.initialize(), hal.initialize()]);
      expect(port.opens).toBe(1);
      expect(hal.isReady()).toBe(true);
      await hal.cleanup();
      expect(hal.isReady()).toBe(false);
      expect((await hal.locomotion.moveForward(5)).code).toBe('NOT_READY');
    });

    it('lets an e-stop through before initialize(), and then refuses motion', async () => {
      const port = new FakePort();
      const hal = new RobotHAL(port);
      const estop = await hal.safety.emergencyStop('before');
      expect(estop).toMatchObject({ success: true, data: { estop: true, delivered: false } });
      await hal.initialize();
      expect((await hal.locomotion.rotate('left', 10)).code).toBe('EMERGENCY_STOPPED');
      const reset = await hal.safety.resetEmergencyStop();
      expect(reset.data).toEqual({ estop: false, wasEmergencyStopped: true });
      expect((await hal.locomotion.rotate('left', 10)).success).toBe(true);
    });
  });

  describe('moveTo', () => {
    it('turns toward the point, then drives along the heading reached', async () => {
      const { hal, port } = await ready();
      const result = await hal.locomotion.moveTo(0.1, 0.1, 0);
      expect(result.success).toBe(true);
      expect(port.commands).toHaveLength(2);
      const [turn, move] = port.commands;
      expect(turn).toMatchObject({ kind: 'rotate' });
      expect((turn as { degrees: number }).degrees).toBeCloseTo(45, 9);
      expect((move as { leftCm: number }).leftCm).toBeCloseTo(Math.hypot(10, 10), 9);
      expect(result.data?.['moves']).toBe(2);
      const pose = result.data?.['pose'] as { x: number; y: number };
      expect(pose.x).toBeCloseTo(0.1, 9);
      expect(pose.y).toBeCloseTo(0.1, 9);
    });

    it('splits a drive longer than one command allows into pieces, none over the limit', async () => {
      const config = { ...V1_ROBOT, maxStepsPerCommand: 2000 };
      const { hal, port } = await ready(new FakePort(config));
      const maxCm = (config.maxStepsPerCommand - 1) / stepsPerCm(config);
      const result = await hal.locomotion.moveTo(0.5, 0, 0);
      expect(result.success).toBe(true);
      const moves = port.commands.filter((c) => c.kind === 'move') as Array<{ leftCm: number }>;
      expect(moves.length).toBe(Math.ceil(50 / maxCm));
      for (const move of moves) expect(move.leftCm).toBeLessThanOrEqual(maxCm);
      expect(moves.reduce((sum, m) => sum + m.leftCm, 0)).toBeCloseTo(50, 9);
    });

    it('sends a speed in m/s as wheel steps/s, and nothing for a target where it stands', async () => {
      const { hal, port } = await ready();
      await hal.locomotion.moveTo(0.1, 0, 0, 0.02);
      expect(port.commands[0]).toMatchObject({ kind: 'move' });
      const sps = (port.commands[0] as { speedStepsPerS: number }).speedStepsPerS;
      expect(sps).toBeCloseTo(2 * stepsPerCm(V1_ROBOT), 9);
      const none = await hal.locomotion.moveTo(0.1, 0, 0);
      expect(none.data?.['moves']).toBe(0);
      expect(port.commands).toHaveLength(1);
    });

    it('asks the port to refuse a target it cannot reach, before anything moves', async () => {
      const port = new FakePort();
      port.checkTarget = (x: number) => {
        if (x > 1) throw Object.assign(new Error('outside'), { code: 'RANGE_EXCEEDED' });
      };
      const { hal } = await ready(port);
      const result = await hal.locomotion.moveTo(2, 0, 0);
      expect(result.success).toBe(false);
      expect(port.commands).toEqual([]);
    });
  });

  describe('drive', () => {
    it('maps power -255..255 to the robot top speed, truncated toward zero', async () => {
      const { hal, port } = await ready();
      await hal.locomotion.drive(255, -100, 250.4);
      const max = V1_ROBOT.maxSpeedStepsPerS;
      expect(port.commands[0]).toEqual({
        kind: 'drive',
        leftSps: max,
        rightSps: Math.trunc((-100 / 255) * max),
        durationMs: 250,
      });
      expect(powerToStepsPerS(1, V1_ROBOT)).toBe(Math.trunc(max / 255));
      expect(powerToStepsPerS(-1, V1_ROBOT)).toBe(-Math.trunc(max / 255));
    });
  });

  describe('sensors', () => {
    it("answers a part the robot lacks NOT_IMPLEMENTED in its world's words", async () => {
      const { hal } = await ready();
      await expect(hal.vision.captureFrame()).rejects.toMatchObject({
        code: 'NOT_IMPLEMENTED',
        message: 'the fake robot has no camera',
      });
      await expect(hal.vision.scan()).rejects.toMatchObject({ code: 'NOT_IMPLEMENTED' });
      await expect(hal.vision.getLineSensors()).rejects.toMatchObject({ code: 'NOT_IMPLEMENTED' });
      const speak = await hal.communication.speak('hello');
      expect(speak).toMatchObject({ success: false, code: 'NOT_IMPLEMENTED' });
    });

    it('makes the IMU from odometry without a measured one, and reads the port with one', async () => {
      const port = new FakePort();
      const { hal } = await ready(port);
      await hal.locomotion.rotate('left', 30);
      const odometry = await hal.vision.getIMU();
      expect(odometry.source).toBe('odometry');
      expect(odometry.heading).toBeCloseTo(Math.PI / 6, 9);
      expect(odometry.gyroscope.z).toBe(0.25);
      port.imu = () => ({
        acceleration: { x: 0, y: 0, z: 0 },
        gyroscope: { x: 0, y: 0, z: 0 },
        heading: 1,
        source: 'simulation',
      });
      expect((await hal.vision.getIMU()).heading).toBe(1);
    });
  });

  describe('log', () => {
    it('keeps the last 1000 messages and reports a refused one to the port', async () => {
      const { hal, port } = await ready();
      for (let i = 0; i < 1005; i += 1) hal.communication.log(`m${i}`);
      expect(hal.logs).toHaveLength(1000);
      expect(hal.logs[0]).toBe('m5');
      expect(port.logged.at(-1)).toEqual(['m1004', 'info']);
      hal.communication.log('x', 'bogus' as 'info');
      expect(port.refusals).toHaveLength(1);
      expect(port.refusals[0]).toMatchObject({ code: 'INVALID_PARAMETER' });
      expect(hal.logs.at(-1)).toBe('m1004');
    });
  });
});
