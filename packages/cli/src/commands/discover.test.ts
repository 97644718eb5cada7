// `hal discover` in-process, against a robot announced on this machine with real mDNS.
import { randomBytes } from 'node:crypto';
import { afterEach, describe, expect, it } from 'vitest';
import { Bonjour } from 'bonjour-service';
import { announceRobot } from '@hal/discovery';
import type { Announcer } from '@hal/discovery';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';

const announcers: Announcer[] = [];
afterEach(async () => {
  await Promise.all(announcers.splice(0).map((a) => a.stop()));
});

async function announce(deviceId: string, port: number, caps = 'locomotion.differential:v1.0') {
  const txt = { txtvers: '1', device_id: deviceId, proto: '1.1', auth: 'none', caps };
  announcers.push(await announceRobot({ port, txt }));
}

describe('hal discover', () => {
  it('lists an announced robot as one JSON line with --json', async () => {
    const id = `cube-cli-${randomBytes(4).toString('hex')}`;
    await announce(id, 41234);
    const io = captureIO();
    expect(await runHal(['--json', 'discover', '--timeout', '2500'], io)).toBe(0);
    const robot = (io.jsonLines() as Record<string, unknown>[]).find((r) => r['deviceId'] === id);
    expect(robot).toMatchObject({
      deviceId: id,
      port: 41234,
      protocolVersion: '1.1',
      auth: 'none',
      requiresKey: false,
      capabilities: ['locomotion.differential:v1.0'],
      onThisMachine: true,
    });
  });

  it('prints a table for people, with the address to use', async () => {
    const id = `cube-cli-${randomBytes(4).toString('hex')}`;
    await announce(id, 41235);
    const io = captureIO();
    expect(await runHal(['discover', '--timeout', '2500'], io)).toBe(0);
    expect(io.stdout()).toMatch(/^DEVICE\s+ADDRESS\s+HOST\s+PROTOCOL\s+AUTH\s+CAPABILITIES/);
    expect(io.stdout()).toMatch(new RegExp(`${id}\\s+127\\.0\\.0\\.1:41235\\s`));
    expect(io.stderr()).toContain('listening for robots for 2500 ms');
  });

  it('warns about a malformed announcement on stderr and leaves it out of the list', async () => {
    const id = `cube-cli-${randomBytes(4).toString('hex')}`;
    // Published around announceRobot, which refuses such a record.
    const raw = new Bonjour();
    raw.publish({
      name: id,
      type: 'hal-cube',
      protocol: 'udp',
      port: 41236,
      txt: { txtvers: '1', device_id: id, proto: '1.1', auth: 'sometimes', caps: '' },
      probe: false,
    });
    try {
      const io = captureIO();
      expect(await runHal(['--json', 'discover', '--timeout', '2500'], io)).toBe(0);
      // with --json the warning is a JSON log line like every command's, nothing else
      const warnings = io
        .stderr()
        .trim()
        .split('\n')
        .map((line) => JSON.parse(line) as { log: { level: string; message: string } });
      expect(warnings).toContainEqual({
        log: expect.objectContaining({
          level: 'warn',
          message: expect.stringMatching(new RegExp(`^skipped "${id}": "auth" must be one of`)),
        }),
      });
      const ids = (io.jsonLines() as Record<string, unknown>[]).map((r) => r['deviceId']);
      expect(ids).not.toContain(id);
    } finally {
      await new Promise<void>((resolve) => raw.unpublishAll(() => raw.destroy(() => resolve())));
    }
  });

  it.each([['0'], ['60001'], ['soon']])('refuses --timeout %s with a usage error', async (t) => {
    const io = captureIO();
    expect(await runHal(['discover', '--timeout', t], io)).toBe(2);
    expect(io.stderr()).toContain('"--timeout" must be an integer in 1..60000');
  });
});
