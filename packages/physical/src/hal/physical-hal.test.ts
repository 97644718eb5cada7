import { describeHalContract } from '@hal/types/testing';
import { describe, expect, it } from 'vitest';
import { MockRobot } from '../mock/mock-robot.js';
import { createAuthenticator } from '../protocol/auth.js';
import { PhysicalHAL } from './physical-hal.js';
import type { PhysicalHALOptions } from './options.js';

// the mock robots get a 10 s host timeout: at 50x that is 200 ms of real time, room for a busy machine
const TIME_SCALE = 50;

function halOn(robot: MockRobot, options: PhysicalHALOptions = {}): PhysicalHAL {
  return new PhysicalHAL(
    { mode: 'physical', deviceId: 'cube-1' },
    { transport: robot.transport(), timeScale: TIME_SCALE, ...options },
  );
}

describeHalContract('PhysicalHAL over the mock robot', {
  create: () => halOn(new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 })),
  timeoutMs: 20_000,
});

describe('PhysicalHAL', () => {
  describe('#initialize', () => {
    it('gives poses in the frame of startPose: where it stands when it connects', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = halOn(robot, { startPose: { x: 1, y: -0.5, yaw: Math.PI / 2 } });
      await hal.initialize();
      const at = await hal.locomotion.getPose();
      expect([at.position.x, at.position.y, at.rotation.yaw]).toEqual([1, -0.5, Math.PI / 2]);
      // facing +y: 20 cm forward is 0.2 m along +y of that frame
      expect(await hal.locomotion.moveForward(20)).toMatchObject({ success: true });
      const moved = await hal.locomotion.getPose();
      expect(moved.position.x).toBeCloseTo(1, 2);
      expect(moved.position.y).toBeCloseTo(-0.3, 2);
      await hal.cleanup();
    });

    it('refuses a startPose that is not finite, before it connects', () => {
      const robot = new MockRobot();
      expect(() => halOn(robot, { startPose: { x: Number.NaN, y: 0, yaw: 0 } })).toThrow(
        expect.objectContaining({
          code: 'INVALID_PARAMETER',
          message: expect.stringContaining('"startPose"'),
        }),
      );
      expect(robot.requests).toHaveLength(0);
    });

    it('fails AUTH_FAILED, not NOT_CONNECTED, when the robot answers with another key', async () => {
      const robot = new MockRobot({ auth: await createAuthenticator('c0ffee') });
      const wrong = new PhysicalHAL(
        {
          mode: 'physical',
          deviceId: 'cube-1',
          connection: { type: 'wifi', host: 'x', key: 'beef' },
        },
        { transport: robot.transport(), requestTimeoutMs: 50, attempts: 20 },
      );
      const error: unknown = await wrong.initialize().catch((e: unknown) => e);
      expect(error).toMatchObject({
        code: 'AUTH_FAILED',
        message: expect.stringContaining('the key is wrong'),
      });
      // and the robot opened no session: nothing it was sent was executed
      expect(robot.requests.filter((r) => r['cmd'] === 'hello')).toHaveLength(0);
      await wrong.cleanup();
    });

    it('fails NOT_CONNECTED, naming the wait, when nothing answers for connectTimeoutMs', async () => {
      const robot = new MockRobot();
      robot.unresponsive = true;
      const hal = new PhysicalHAL(
        { mode: 'physical', deviceId: 'cube-1' },
        { transport: robot.transport(), requestTimeoutMs: 50, connectTimeoutMs: 400 },
      );
      await expect(hal.initialize()).rejects.toMatchObject({
        code: 'NOT_CONNECTED',
        message: 'the robot did not answer "hello" within 400 ms (8 attempts)',
        details: { command: 'hello', attempts: 8, waitedMs: 400 },
      });
      await hal.cleanup();
    });
  });

  describe('#moveForward', () => {
    it('sends one move_cm and resolves once the robot reports the move done', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = halOn(robot);
      await hal.initialize();
      const result = await hal.locomotion.moveForward(10);
      expect(result.success, JSON.stringify(result)).toBe(true);
      expect(robot.position).toEqual({ left: 2172, right: 2172 });
      expect(robot.requests.filter((r) => r['cmd'] === 'move_cm')).toHaveLength(1);
      expect(robot.requests.find((r) => r['cmd'] === 'move_cm')).toMatchObject({
        left_cm: 10,
        right_cm: 10,
        sid: expect.any(Number),
        seq: expect.any(Number),
      });
      expect(robot.lastRequest?.['cmd']).toBe('get_status');
      expect(result.data).toMatchObject({ leftSteps: 2172, rightSteps: 2172 });
      await hal.cleanup();
    });

    it('executes a move once when its reply is lost and the request is retried', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = new PhysicalHAL(
        { mode: 'physical', deviceId: 'cube-1' },
        { transport: robot.transport(), timeScale: TIME_SCALE },
      );
      await hal.initialize();
      robot.dropReplies(2);
      const result = await hal.locomotion.moveForward(10);
      expect(result.success, JSON.stringify(result)).toBe(true);
      expect(robot.motionsStarted).toBe(1);
      expect(robot.position).toEqual({ left: 2172, right: 2172 });
      expect(hal.transportStats()?.retries).toBe(2);
      await hal.cleanup();
    });

    it('fails with NOT_CONNECTED when the robot stops answering, and recovers when it is back', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = new PhysicalHAL(
        { mode: 'physical', deviceId: 'cube-1' },
        {
          transport: robot.transport(),
          timeScale: TIME_SCALE,
          requestTimeoutMs: 20,
          attempts: 2,
          reconnectIntervalMs: 20,
        },
      );
      await hal.initialize();
      robot.unresponsive = true;
      const lost = await hal.locomotion.moveForward(1);
      expect(lost.code).toBe('NOT_CONNECTED');
      expect(hal.isReady()).toBe(false);
      expect((await hal.locomotion.moveForward(1)).code).toBe('NOT_CONNECTED');
      robot.unresponsive = false;
      await expect.poll(() => hal.isReady(), { timeout: 5000 }).toBe(true);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
      await hal.cleanup();
    });
  });

  describe('#rotate', () => {
    it('turns 90 degrees with 1706 steps per wheel, left wheel backwards', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = halOn(robot);
      await hal.initialize();
      expect((await hal.locomotion.rotate('left', 90)).success).toBe(true);
      expect(robot.position).toEqual({ left: -1706, right: 1706 });
      await hal.cleanup();
    });
  });

  describe('#stop', () => {
    it('interrupts a running move, which resolves with INTERRUPTED', async () => {
      const robot = new MockRobot({ timeScale: 5, hostTimeoutMs: 10_000 });
      const hal = halOn(robot, { timeScale: 5 });
      await hal.initialize();
      const move = hal.locomotion.moveForward(20);
      await expect.poll(() => robot.position.left, { timeout: 5000 }).toBeGreaterThan(100);
      expect((await hal.locomotion.stop()).success).toBe(true);
      const result = await move;
      expect(result.code).toBe('INTERRUPTED');
      const stoppedAt = robot.position.left;
      expect(stoppedAt).toBeLessThan(4345);
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(stoppedAt / (4096 / (Math.PI * 6)) / 100, 6);
      await hal.cleanup();
    });
  });

  describe('session', () => {
    it('says hello again after the robot restarts and keeps the pose', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = new PhysicalHAL(
        { mode: 'physical', deviceId: 'cube-1' },
        { transport: robot.transport(), timeScale: TIME_SCALE, reconnectIntervalMs: 10 },
      );
      await hal.initialize();
      expect((await hal.locomotion.moveForward(5)).success).toBe(true);
      robot.restart();
      const refused = await hal.locomotion.moveForward(5);
      expect(refused.code).toBe('NOT_CONNECTED');
      await expect.poll(() => hal.isReady(), { timeout: 5000 }).toBe(true);
      expect((await hal.locomotion.moveForward(5)).success).toBe(true);
      await hal.refreshStatus();
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(0.1, 3);
      await hal.cleanup();
    });
  });

  describe('a restart during a motion', () => {
    it('fails the motion INTERRUPTED, saying the robot restarted, and does not resume it', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = new PhysicalHAL(
        { mode: 'physical', deviceId: 'cube-1' },
        { transport: robot.transport(), timeScale: TIME_SCALE, reconnectIntervalMs: 10 },
      );
      await hal.initialize();
      // about 21 s of robot time, 430 ms here: the host reconnects long before its first poll
      const running = hal.locomotion.moveForward(100);
      await expect.poll(() => robot.motionsStarted, { timeout: 5000 }).toBe(1);
      robot.restart();
      const result = await running;
      expect(result.code).toBe('INTERRUPTED');
      expect(result.error).toMatch(/restarted/);
      expect(robot.motionsStarted).toBe(1);
      expect((await hal.refreshStatus()).move_id).toBe(0);
      await hal.cleanup();
    });
  });

  describe('#moveTo', () => {
    it(
      'splits a straight leg longer than one command allows into several moves',
      { timeout: 30_000 },
      async () => {
        // x20, slower than the others: the robot's 10 s host timeout is then 500 ms of real time, more
        // than a loaded machine holds back a heartbeat (at x50, 200 ms, the leg was cut in a full
        // run beside other work; at x200, 50 ms, often)
        const scale = 20;
        const robot = new MockRobot({ timeScale: scale, hostTimeoutMs: 10_000 });
        const hal = halOn(robot, { timeScale: scale });
        await hal.initialize();
        const result = await hal.locomotion.moveTo(0, 2.5, 0);
        expect(result.success, JSON.stringify(result)).toBe(true);
        const moves = robot.requests.filter((r) => r['cmd'] === 'move_cm');
        expect(moves.length).toBe(2);
        for (const move of moves) expect(Number(move['left_cm']) * 217.3).toBeLessThan(40960);
        const pose = await hal.locomotion.getPose();
        // whole steps: the heading is good to one step (~0.0009 rad), ~2 mm sideways over 2.5 m
        expect(Math.abs(pose.position.y - 2.5)).toBeLessThan(0.001);
        expect(Math.abs(pose.position.x)).toBeLessThan(0.003);
        await hal.cleanup();
      },
    );
  });

  describe('#drive', () => {
    it('keeps driving after it resolves when no duration is given, until stop()', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = halOn(robot);
      await hal.initialize();
      const result = await hal.locomotion.drive(255, 128);
      expect(result.success).toBe(true);
      expect(result.data).toMatchObject({ running: true, leftSps: 1024, rightSps: 514 });
      await expect.poll(() => robot.position.left, { timeout: 5000 }).toBeGreaterThan(50);
      expect((await hal.locomotion.getPose()).velocity.linear).toBeGreaterThan(0);
      expect((await hal.locomotion.stop()).success).toBe(true);
      const stopped = robot.position.left;
      expect((await hal.locomotion.getPose()).velocity.linear).toBe(0);
      await new Promise((resolve) => setTimeout(resolve, 30));
      expect(robot.position.left).toBe(stopped);
      await hal.cleanup();
    });
  });

  describe('#log', () => {
    it('writes to the injected logger, never the console', async () => {
      const entries: unknown[][] = [];
      const hal = halOn(new MockRobot(), {
        logger: { log: (...entry) => entries.push(entry) },
      });
      await hal.initialize();
      hal.communication.log('battery low', 'warn');
      expect(entries).toContainEqual([
        'warn',
        'hal:physical:log',
        'battery low',
        { deviceId: 'cube-1' },
      ]);
      await hal.cleanup();
    });

    it('never throws: a refused call records nothing and is reported at warn level', async () => {
      const entries: unknown[][] = [];
      const hal = halOn(new MockRobot(), {
        logger: { log: (...entry) => entries.push(entry) },
      });
      expect(() => hal.communication.log('too early', 'info')).not.toThrow();
      await hal.initialize();
      expect(() => hal.communication.log('x', 'bogus' as 'info')).not.toThrow();
      expect(() => hal.communication.log(42 as unknown as string)).not.toThrow();
      const logged = entries.filter((e) => e[1] === 'hal:physical:log');
      expect(logged.map((e) => [e[0], e[2]])).toEqual([
        ['warn', 'log refused'],
        ['warn', 'log refused'],
        ['warn', 'log refused'],
      ]);
      expect(logged[0]?.[3]).toMatchObject({ code: 'NOT_READY' });
      expect(logged[1]?.[3]).toMatchObject({
        code: 'INVALID_PARAMETER',
        error: expect.stringContaining('"level"'),
      });
      expect(logged[2]?.[3]).toMatchObject({
        code: 'INVALID_PARAMETER',
        error: expect.stringContaining('"message"'),
      });
      await hal.cleanup();
    });
  });

  describe('#getIMU', () => {
    it('reports the heading from odometry, marked with its source', async () => {
      const hal = halOn(new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 }));
      await hal.initialize();
      await hal.locomotion.rotate('left', 45);
      const imu = await hal.vision.getIMU();
      expect(imu.source).toBe('odometry');
      expect(imu.heading).toBeCloseTo(Math.PI / 4, 2);
      await hal.cleanup();
    });
  });

  describe('#emergencyStop', () => {
    it('stays latched on the host when the stop cannot reach the robot, and stops it on reconnection', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = halOn(robot, { requestTimeoutMs: 20, attempts: 2, reconnectIntervalMs: 20 });
      await hal.initialize();
      robot.unresponsive = true;
      const stop = await hal.safety.emergencyStop('link test');
      expect(stop.code).toBe('NOT_CONNECTED');
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('link test');
      robot.restart();
      robot.unresponsive = false;
      await expect.poll(() => robot.estopped, { timeout: 5000 }).toBe(true);
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      expect(robot.estopped).toBe(false);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
      await hal.cleanup();
    });

    it('learns of a latch the robot set by itself from its refusal', async () => {
      const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
      const hal = halOn(robot);
      await hal.initialize();
      // another host trips the robot's step limit
      robot.handle(new TextEncoder().encode('{"cmd":"move_steps","left":50000,"right":0}'));
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect(hal.safety.getSafetyStatus().emergencyStopReason).toContain('step limit');
      await hal.cleanup();
    });
  });

  describe('config', () => {
    it('refuses a link type it has no transport for, naming the supported ones', () => {
      const build = () =>
        new PhysicalHAL({
          mode: 'physical',
          deviceId: 'cube-1',
          connection: { type: 'bluetooth' as 'serial' },
        });
      expect(build).toThrow(/"connection\.type".*one of "serial", "wifi".*got "bluetooth"/);
      expect(build).toThrow(expect.objectContaining({ code: 'INVALID_PARAMETER' }));
    });
  });

  describe('#getDistanceSensors', () => {
    it('rejects with NOT_IMPLEMENTED: the V1 robot has no range sensors', async () => {
      const hal = halOn(new MockRobot());
      await hal.initialize();
      await expect(hal.vision.getDistanceSensors()).rejects.toMatchObject({
        code: 'NOT_IMPLEMENTED',
      });
      await hal.cleanup();
    });
  });
});
