// Real mDNS on this machine (224.0.0.251:5353): the announcer and the browser in one process.
// tests/discovery/ runs them in two.
import { randomBytes } from 'node:crypto';
import { afterEach, describe, expect, it } from 'vitest';
import { Bonjour } from 'bonjour-service';
import { HalError } from '@hal/types';
import type { Logger } from '@hal/types';
import { announceRobot } from './announce.js';
import type { Announcer } from './announce.js';
import { discoverRobots, findRobot } from './discover.js';

const uniqueId = (prefix: string) => `${prefix}-${randomBytes(4).toString('hex')}`;

function txtFor(deviceId: string, auth = 'none') {
  return {
    txtvers: '1',
    device_id: deviceId,
    proto: '1.1',
    auth,
    caps: 'locomotion.differential:v1.0,safety.estop:v1.0',
  };
}

function recordingLogger() {
  const entries: { level: string; namespace: string; message: string }[] = [];
  const logger: Logger = {
    log: (level, namespace, message) => entries.push({ level, namespace, message }),
  };
  return { logger, entries };
}

const cleanups: (() => Promise<void>)[] = [];
afterEach(async () => {
  await Promise.all(cleanups.splice(0).map((f) => f()));
});

async function announce(deviceId: string, port: number, auth?: string): Promise<Announcer> {
  const announcer = await announceRobot({ port, txt: txtFor(deviceId, auth) });
  cleanups.push(() => announcer.stop());
  return announcer;
}

describe('discoverRobots', () => {
  it('finds an announced robot with its id, port, protocol, auth and capabilities', async () => {
    const id = uniqueId('cube-unit');
    await announce(id, 40123, 'hmac-sha256');
    const robots = await discoverRobots({ timeoutMs: 2500 });
    const robot = robots.find((r) => r.deviceId === id);
    expect(robot).toMatchObject({
      deviceId: id,
      name: id,
      port: 40123,
      protocolVersion: '1.1',
      auth: 'hmac-sha256',
      requiresKey: true,
      capabilities: ['locomotion.differential:v1.0', 'safety.estop:v1.0'],
      onThisMachine: true,
    });
    expect(robot?.addresses.length).toBeGreaterThan(0);
  });

  it('skips a robot with a malformed TXT record, logs why, and still returns the good ones', async () => {
    const good = uniqueId('cube-good');
    const bad = uniqueId('cube-bad');
    await announce(good, 40124);
    // Published around announceRobot, which would refuse it.
    const raw = new Bonjour();
    raw.publish({
      name: bad,
      type: 'hal-cube',
      protocol: 'udp',
      port: 40125,
      txt: { ...txtFor(bad), caps: 'not-a-capability' },
      probe: false,
    });
    cleanups.push(
      () => new Promise((resolve) => raw.unpublishAll(() => raw.destroy(() => resolve()))),
    );
    const { logger, entries } = recordingLogger();
    const robots = await discoverRobots({ timeoutMs: 2500, logger });
    const ids = robots.map((r) => r.deviceId);
    expect(ids).toContain(good);
    expect(ids).not.toContain(bad);
    const skipped = entries.find((e) => e.message.includes(bad));
    expect(skipped).toMatchObject({ level: 'warn', namespace: 'hal:discovery' });
    expect(skipped?.message).toContain('not-a-capability');
  });

  it('ends early when its signal aborts', async () => {
    const stop = new AbortController();
    const started = performance.now();
    setTimeout(() => stop.abort(), 100);
    await discoverRobots({ timeoutMs: 30_000, signal: stop.signal });
    expect(performance.now() - started).toBeLessThan(10_000); // did not wait the 30 s
  });

  it.each([0, -5, 60_001, Number.NaN, Number.POSITIVE_INFINITY])(
    'refuses a timeout of %s ms with a typed error',
    async (timeoutMs) => {
      await expect(discoverRobots({ timeoutMs })).rejects.toThrow(/"timeoutMs" must be/);
    },
  );
});

describe('findRobot', () => {
  it('resolves as soon as the robot answers', async () => {
    const id = uniqueId('cube-find');
    await announce(id, 40126);
    const started = performance.now();
    const robot = await findRobot(id, { timeoutMs: 20_000 });
    expect(robot.port).toBe(40126);
    expect(performance.now() - started).toBeLessThan(15_000); // not the whole 20 s
  });

  it('fails with TIMEOUT when the robot never answers', async () => {
    const error = await findRobot(uniqueId('cube-absent'), { timeoutMs: 300 }).catch((e) => e);
    expect(error).toBeInstanceOf(HalError);
    expect(error).toMatchObject({ code: 'TIMEOUT' });
  });
});

describe('announceRobot', () => {
  it('refuses a TXT record discovery would skip, before opening a socket', async () => {
    await expect(
      announceRobot({ port: 4210, txt: { ...txtFor('cube-x'), auth: 'maybe' } }),
    ).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
    await expect(
      announceRobot({ port: 4210, txt: { ...txtFor('cube-x'), note: 'x'.repeat(300) } }),
    ).rejects.toThrow(/"note" is over 255 bytes/);
    await expect(announceRobot({ port: 0, txt: txtFor('cube-x') })).rejects.toThrow(/"port"/);
  });

  it('stops answering once stopped, so a later search no longer finds the robot', async () => {
    const id = uniqueId('cube-bye');
    const announcer = await announceRobot({ port: 40127, txt: txtFor(id) });
    await findRobot(id, { timeoutMs: 5000 });
    await announcer.stop();
    const robots = await discoverRobots({ timeoutMs: 1500 });
    expect(robots.map((r) => r.deviceId)).not.toContain(id);
  });
});
