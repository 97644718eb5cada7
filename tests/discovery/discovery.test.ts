// Finding robots across processes on this machine (docs/discovery.md): `hal emulate` runs the
// emulated robot and announces it with real mDNS in one process; this test process discovers it,
// builds a PhysicalHAL from what it found, and drives the robot over UDP.
import { randomBytes } from 'node:crypto';
import { afterAll, describe, expect, it } from 'vitest';
import {
  createPhysicalHALFromDiscovery,
  discoverRobots,
  findRobot,
  physicalHalConfigFor,
} from '@hal/discovery';
import { EMULATOR_PATH, requireEmulator } from '../physical/emulator.js';
import { startHalProcess, stopAllHal } from '../helpers/hal-process.js';
import type { HalProcess } from '../helpers/hal-process.js';

/** A `hal --json` line: an event, or one of discover's robots (which have no `event`). */
type HalLine = Record<string, unknown> & { event: string };
const startHal = (args: readonly string[]) => startHalProcess<HalLine>(['--json', ...args]);

const KEY = '00112233445566778899aabbccddeeff';
const TIME_SCALE = 5;

afterAll(stopAllHal);

const uniqueId = (prefix: string) => `${prefix}-${randomBytes(4).toString('hex')}`;

async function emulate(deviceId: string, extra: string[] = []): Promise<HalProcess<HalLine>> {
  requireEmulator();
  const hal = startHal([
    'emulate',
    '--emulator',
    EMULATOR_PATH,
    '--udp-port',
    '0',
    '--no-pty',
    '--time-scale',
    String(TIME_SCALE),
    '--device-id',
    deviceId,
    ...extra,
  ]);
  await hal.waitFor((l) => l.event === 'ready');
  return hal;
}

describe('discovery between processes', () => {
  it('finds the robot `hal emulate` announces, and a PhysicalHAL built from it drives that robot', async () => {
    const id = uniqueId('cube-disc');
    const emulator = await emulate(id);
    const ready = await emulator.waitFor((l) => l.event === 'ready');

    const robot = await findRobot(id, { timeoutMs: 10_000 });
    expect(robot).toMatchObject({
      deviceId: id,
      port: ready['udpPort'],
      protocolVersion: '1.1',
      auth: 'none',
      requiresKey: false,
      onThisMachine: true,
    });

    const hal = createPhysicalHALFromDiscovery(robot, { hal: { timeScale: TIME_SCALE } });
    try {
      await hal.initialize();
      expect(hal.isReady()).toBe(true);
      // What the robot announced is what it says in hello.
      expect(hal.getDeviceInfo().capabilities).toEqual(robot.capabilities);
      const moved = await hal.locomotion.moveForward(5);
      expect(moved.success, moved.error).toBe(true);
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(0.05, 2);
      // The emulator in the other process reports the move it made.
      const finished = await emulator.waitFor((l) => l.event === 'move_finished');
      expect(finished['outcome']).toBe('done');
    } finally {
      await hal.cleanup();
    }

    expect(await emulator.stop()).toBe(0);
    expect(emulator.events).toContainEqual({ event: 'stopped', deviceId: id });
  });

  it('says a keyed robot needs its key, and drives it with the key', async () => {
    const id = uniqueId('cube-keyed');
    const emulator = await emulate(id, ['--key', KEY]);
    const robot = await findRobot(id, { timeoutMs: 10_000 });
    expect(robot).toMatchObject({ auth: 'hmac-sha256', requiresKey: true });
    expect(() => physicalHalConfigFor(robot)).toThrow(/requires its key/);

    const hal = createPhysicalHALFromDiscovery(robot, {
      key: KEY,
      hal: { timeScale: TIME_SCALE },
    });
    try {
      await hal.initialize();
      expect(hal.isReady()).toBe(true);
      const moved = await hal.locomotion.moveForward(2);
      expect(moved.success, moved.error).toBe(true);
    } finally {
      await hal.cleanup();
    }
    await emulator.stop();
  });

  it('`hal discover` in a third process lists the robot until `hal emulate` is stopped', async () => {
    const id = uniqueId('cube-listed');
    const emulator = await emulate(id);

    const discover = startHal(['discover', '--timeout', '2500']);
    expect(await discover.exited).toBe(0);
    const listed = discover.events.find((l) => l['deviceId'] === id);
    expect(listed).toMatchObject({ deviceId: id, onThisMachine: true, auth: 'none' });

    expect(await emulator.stop()).toBe(0);
    const after = await discoverRobots({ timeoutMs: 1500 });
    expect(after.map((r) => r.deviceId)).not.toContain(id);
  });
});
