// The seed's scenarios, through PhysicalHAL against the emulated robot, over both links.
import { createSocket } from 'node:dgram';
import { PhysicalHAL } from '@hal/physical';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import type { Emulator, EmulatorEvent } from './emulator.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 10;
const HOST_TIMEOUT_MS = 2000;

type Link = 'udp' | 'serial';

function connect(emulator: Emulator, link: Link, key?: string): PhysicalHAL {
  const connection =
    link === 'udp'
      ? { type: 'wifi' as const, host: '127.0.0.1', udpPort: emulator.udpPort }
      : { type: 'serial' as const, port: emulator.pty, baudRate: 115200 };
  return new PhysicalHAL(
    {
      mode: 'physical',
      deviceId: `cube-${link}`,
      connection: key === undefined ? connection : { ...connection, key },
    },
    { timeScale: TIME_SCALE, reconnectIntervalMs: 50 },
  );
}

const finished = (moveId: number) => (e: EmulatorEvent) =>
  e.event === 'move_finished' && e['move_id'] === moveId;

for (const link of ['udp', 'serial'] as const) {
  describe(`PhysicalHAL over ${link} against the emulator`, () => {
    let emulator: Emulator;
    let hal: PhysicalHAL;

    async function start(options: { key?: string } = {}): Promise<void> {
      emulator = await startEmulator({
        timeScale: TIME_SCALE,
        hostTimeoutMs: HOST_TIMEOUT_MS,
        ...options,
      });
      hal = connect(emulator, link, options.key);
      await hal.initialize();
    }

    afterEach(async () => {
      await hal?.cleanup();
      await emulator?.stop();
    });

    it('moves 10 cm: 2172 steps on each wheel, and the pose says 0.1 m ahead', async () => {
      await start();
      const result = await hal.locomotion.moveForward(10);
      expect(result.success, JSON.stringify(result)).toBe(true);
      const event = await emulator.waitFor(finished(1));
      expect(event).toMatchObject({ outcome: 'done', left_steps: 2172, right_steps: 2172 });
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(Number(event['x_cm']) / 100, 9);
      expect(pose.position.x).toBeCloseTo(0.1, 3);
    });

    it('turns 90 degrees left: 1706 steps per wheel, left wheel backwards', async () => {
      await start();
      expect((await hal.locomotion.rotate('left', 90)).success).toBe(true);
      const event = await emulator.waitFor(finished(1));
      expect(event).toMatchObject({ outcome: 'done', left_steps: -1706, right_steps: 1706 });
      const pose = await hal.locomotion.getPose();
      expect(pose.rotation.yaw).toBeCloseTo(Number(event['heading_rad']), 9);
      expect(pose.rotation.yaw).toBeCloseTo(Math.PI / 2, 2);
    });

    it('moves to a point, turning toward it and driving straight', async () => {
      await start();
      const result = await hal.locomotion.moveTo(0.3, -0.2, 0);
      expect(result.success, JSON.stringify(result)).toBe(true);
      const pose = await hal.locomotion.getPose();
      expect(Math.hypot(pose.position.x - 0.3, pose.position.y + 0.2)).toBeLessThan(0.002);
      expect(result.data?.['moves']).toBe(2);
      const last = await emulator.waitFor(finished(2));
      // the host integrates each status's step deltas as one exact arc, the firmware step by
      // step; over the slave wheel's Bresenham steps the two agree to a tenth of a millimetre
      expect(Math.abs(pose.position.x - Number(last['x_cm']) / 100)).toBeLessThan(1e-4);
      expect(Math.abs(pose.position.y - Number(last['y_cm']) / 100)).toBeLessThan(1e-4);
      expect(pose.rotation.yaw).toBeCloseTo(Number(last['heading_rad']), 9);
    });

    it('stops mid-move: the move resolves INTERRUPTED where the robot stopped', async () => {
      await start();
      const move = hal.locomotion.moveForward(30);
      await emulator.waitFor((e) => e.event === 'move_started');
      // stopped once the wheels have turned, so the stop lands mid-move
      await expect
        .poll(async () => (await hal.refreshStatus()).move_left_steps, { timeout: 5000 })
        .toBeGreaterThan(0);
      expect((await hal.locomotion.stop()).success).toBe(true);
      const result = await move;
      expect(result.code).toBe('INTERRUPTED');
      const event = await emulator.waitFor(finished(1));
      expect(event['outcome']).toBe('stopped');
      expect(Number(event['left_steps'])).toBeLessThan(6517);
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(Number(event['x_cm']) / 100, 9);
    });

    it('e-stops mid-move, refuses motion while latched, and moves again after the reset', async () => {
      await start();
      const move = hal.locomotion.moveForward(30);
      await emulator.waitFor((e) => e.event === 'move_started');
      expect((await hal.safety.emergencyStop('test')).success).toBe(true);
      expect((await move).code).toBe('EMERGENCY_STOPPED');
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect(hal.safety.getSafetyStatus()).toMatchObject({
        emergencyStopped: true,
        emergencyStopReason: 'test',
      });
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    });

    it('keeps a move longer than the host timeout alive with heartbeats', async () => {
      await start();
      // 10 cm takes 4.1 s of robot time, twice the 2000 ms host timeout
      expect((await hal.locomotion.moveForward(10)).success).toBe(true);
      const drive = await hal.locomotion.drive(120, 120);
      expect(drive.success).toBe(true);
      // an agent thinking: nothing but heartbeats for 5 host timeouts
      await new Promise((resolve) => setTimeout(resolve, (5 * HOST_TIMEOUT_MS) / TIME_SCALE));
      expect(emulator.events.filter((e) => e.event === 'trip')).toEqual([]);
      expect((await hal.refreshStatus()).running).toBe(true);
      expect((await hal.locomotion.stop()).success).toBe(true);
    });

    it('is stopped by the robot when the host goes silent (heartbeat paused)', async () => {
      await start();
      expect((await hal.locomotion.drive(120, 120)).success).toBe(true);
      hal.pauseHeartbeat();
      const trip = await emulator.waitFor((e) => e.event === 'trip', 10_000);
      expect(trip['reason']).toBe('host_timeout');
      hal.resumeHeartbeat();
      const status = await hal.refreshStatus();
      expect(status.running).toBe(false);
      expect(status.move_outcome).toBe('host_timeout');
      expect(hal.safety.getSafetyStatus().errors.join(' ')).toContain('host_timeout');
      // not latched: the next command runs
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    });

    it('reports NOT_CONNECTED when another host takes the session, then says hello again', async () => {
      await start();
      const intruder = createSocket('udp4');
      await new Promise<void>((resolve) => {
        intruder.once('message', () => resolve());
        intruder.send('{"cmd":"hello","seq":1}', emulator.udpPort, '127.0.0.1');
      });
      intruder.close();
      const refused = await hal.locomotion.moveForward(1);
      expect(refused.code).toBe('NOT_CONNECTED');
      await expect.poll(() => hal.isReady(), { timeout: 10_000 }).toBe(true);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    });

    it('authenticates every message when a key is configured', async () => {
      await start({ key: '0123456789abcdef' });
      expect(hal.identity).toMatchObject({ auth: true, authScheme: 'hmac-sha256' });
      expect((await hal.locomotion.moveForward(2)).success).toBe(true);
      expect((await hal.communication.setLED(0, 128, 255, 'blink')).success).toBe(true);
      const status = await hal.refreshStatus();
      expect(status.led).toEqual({ r: 0, g: 128, b: 255, pattern: 'blink' });
    });
  });
}

describe('PhysicalHAL against an emulator that requires a key', () => {
  it('fails to initialise with AUTH_FAILED when it has no key', async () => {
    const emulator = await startEmulator({ key: 'c0ffee', pty: false });
    const hal = connect(emulator, 'udp');
    try {
      await expect(hal.initialize()).rejects.toMatchObject({ code: 'AUTH_FAILED' });
      expect(hal.isReady()).toBe(false);
    } finally {
      await hal.cleanup();
      await emulator.stop();
    }
  });

  it('never accepts a reply signed with another key, and says the key is wrong', async () => {
    const emulator = await startEmulator({ key: 'c0ffee', pty: false });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-wrong-key',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort, key: 'beef' },
      },
      { requestTimeoutMs: 50, attempts: 3 },
    );
    try {
      // the robot answered with its own key: AUTH_FAILED, not the silence of NOT_CONNECTED
      await expect(hal.initialize()).rejects.toMatchObject({
        code: 'AUTH_FAILED',
        message: expect.stringContaining('the key is wrong'),
      });
      expect(hal.isReady()).toBe(false);
    } finally {
      await hal.cleanup();
      await emulator.stop();
    }
  });
});

describe('PhysicalHAL when the robot goes away', () => {
  it('gives NOT_CONNECTED while it is gone and recovers with a new session when it is back', async () => {
    let emulator = await startEmulator({ timeScale: TIME_SCALE, pty: false });
    const port = emulator.udpPort;
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-lost',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: port },
      },
      { timeScale: TIME_SCALE, requestTimeoutMs: 50, attempts: 3, reconnectIntervalMs: 50 },
    );
    try {
      await hal.initialize();
      expect((await hal.locomotion.moveForward(5)).success).toBe(true);
      await emulator.stop();
      expect((await hal.locomotion.moveForward(5)).code).toBe('NOT_CONNECTED');
      expect(hal.isReady()).toBe(false);
      expect((await hal.locomotion.rotate('left', 10)).code).toBe('NOT_CONNECTED');
      emulator = await startEmulator({ timeScale: TIME_SCALE, pty: false, udpPort: port });
      await expect.poll(() => hal.isReady(), { timeout: 10_000 }).toBe(true);
      // the restarted robot counts from zero; the host keeps the pose it had
      expect((await hal.locomotion.moveForward(5)).success).toBe(true);
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(0.1, 3);
    } finally {
      await hal.cleanup();
      await emulator.stop();
    }
  });
});
