// MockUdpRobot on real UDP sockets on 127.0.0.1, driven by PhysicalHAL through its own UDP
// transport (the HAL is given only `connection`, as a user's test gives it).
import { createSocket } from 'node:dgram';
import { describeHalContract } from '@hal/types/testing';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { PhysicalHAL } from '../hal/physical-hal.js';
import { MockUdpRobot } from './udp-robot.js';
import type { MockUdpRobotOptions } from './udp-robot.js';

// a 10 s host timeout at 50x is 200 ms of real time: room for a busy machine
const TIME_SCALE = 50;
const robots = new Map<HardwareAbstractionLayer, MockUdpRobot>();

async function halOnUdp(
  options: MockUdpRobotOptions = {},
): Promise<{ robot: MockUdpRobot; hal: PhysicalHAL }> {
  const robot = await MockUdpRobot.start({
    timeScale: TIME_SCALE,
    hostTimeoutMs: 10_000,
    ...options,
  });
  const hal = new PhysicalHAL(
    { mode: 'physical', deviceId: 'cube-udp', connection: robot.connection },
    { timeScale: options.timeScale ?? TIME_SCALE },
  );
  robots.set(hal, robot);
  return { robot, hal };
}

describeHalContract('PhysicalHAL over UDP to MockUdpRobot', {
  create: async () => (await halOnUdp()).hal,
  dispose: async (hal) => {
    await robots.get(hal)?.close();
    robots.delete(hal);
  },
  timeoutMs: 20_000,
});

/** One datagram to `port`, and the reply to it (at most `timeoutMs`). */
async function exchange(port: number, bytes: Uint8Array, timeoutMs = 2000): Promise<string> {
  const socket = createSocket('udp4');
  try {
    return await new Promise<string>((resolve, reject) => {
      const timer = setTimeout(
        () => reject(new Error(`no reply within ${timeoutMs} ms`)),
        timeoutMs,
      );
      socket.once('message', (message) => {
        clearTimeout(timer);
        resolve(message.toString());
      });
      socket.send(bytes, port, '127.0.0.1');
    });
  } finally {
    socket.close();
  }
}

describe('MockUdpRobot', () => {
  const cleanups: Array<() => Promise<unknown>> = [];
  afterEach(async () => {
    for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
  });

  async function started(options: MockUdpRobotOptions = {}) {
    const made = await halOnUdp(options);
    cleanups.push(
      () => made.robot.close(),
      () => made.hal.cleanup(),
    );
    return made;
  }

  it('listens on 127.0.0.1 on a free port, and PhysicalHAL drives it over the wire', async () => {
    const { robot, hal } = await started({ deviceId: 'cube-test' });
    expect(robot.host).toBe('127.0.0.1');
    expect(robot.port).toBeGreaterThan(0);
    expect(robot.connection).toEqual({ type: 'wifi', host: '127.0.0.1', udpPort: robot.port });
    await hal.initialize();
    expect(hal.identity).toMatchObject({ deviceId: 'cube-test', authScheme: 'none' });
    const moved = await hal.locomotion.moveForward(5);
    expect(moved.success).toBe(true);
    // 5 cm of a 6 cm wheel at 4096 steps a turn
    expect(robot.position.left).toBe(Math.round((5 / (6 * Math.PI)) * 4096));
    expect(robot.position.right).toBe(robot.position.left);
    expect(robot.requests.map((r) => r['cmd'])).toContain('move_cm');
  });

  it('with a key, MACs every message: the right key drives it, another is refused', async () => {
    const { robot, hal } = await started({ key: 'c0ffee' });
    expect(robot.connection.key).toBe('c0ffee');
    await hal.initialize();
    expect(hal.identity?.authScheme).toBe('hmac-sha256');
    expect((await hal.locomotion.rotate('left', 90)).success).toBe(true);

    const wrong = new PhysicalHAL(
      { mode: 'physical', deviceId: 'x', connection: { ...robot.connection, key: 'beef' } },
      { requestTimeoutMs: 50, attempts: 20, timeScale: TIME_SCALE },
    );
    cleanups.push(() => wrong.cleanup());
    await expect(wrong.initialize()).rejects.toMatchObject({ code: 'AUTH_FAILED' });
  });

  it('has the fault helpers: a lost reply is resent and answered from memory, the move made once', async () => {
    const { robot, hal } = await started();
    await hal.initialize();
    robot.dropReplies(1);
    expect((await hal.locomotion.moveForward(2)).success).toBe(true);
    expect(robot.motionsStarted).toBe(1);
    const moves = robot.requests.filter((r) => r['cmd'] === 'move_cm');
    expect(moves).toHaveLength(2);
    expect(moves[1]!['seq']).toBe(moves[0]!['seq']);
  });

  it('answers a datagram longer than 1024 bytes with MALFORMED, as the firmware does', async () => {
    const { robot } = await started();
    const long = new TextEncoder().encode(
      JSON.stringify({ cmd: 'get_status', pad: 'x'.repeat(1100) }),
    );
    const reply = JSON.parse(await exchange(robot.port, long)) as Record<string, unknown>;
    expect(reply).toMatchObject({ ok: false, error: { code: 'MALFORMED' } });
  });

  it('refuses a port in use with NOT_CONNECTED naming EADDRINUSE, and bad options with INVALID_PARAMETER', async () => {
    const { robot } = await started();
    await expect(MockUdpRobot.start({ port: robot.port })).rejects.toMatchObject({
      code: 'NOT_CONNECTED',
      message: expect.stringContaining('EADDRINUSE'),
    });
    await expect(MockUdpRobot.start({ key: 'xyz' })).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
    });
    await expect(MockUdpRobot.start({ host: 'localhost' })).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
    });
    await expect(MockUdpRobot.start({ port: 70_000 })).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
    });
  });

  it('close() releases the port (twice is fine)', async () => {
    const robot = await MockUdpRobot.start();
    const port = robot.port;
    await robot.close();
    await robot.close();
    const again = await MockUdpRobot.start({ port });
    expect(again.port).toBe(port);
    await again.close();
  });
});
