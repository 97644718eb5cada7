// The @hal/discovery README's example, run as written (only the device id changes) against the
// emulator in another process, announced with the record it printed.
import { randomBytes } from 'node:crypto';
import { readFileSync } from 'node:fs';
import * as discovery from '@hal/discovery';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { afterAll, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';

afterAll(stopAllEmulators);

const readme = readFileSync(new URL('../../packages/discovery/README.md', import.meta.url), 'utf8');
const blocks = fencedBlocks(readme, 'ts');

it('README: finds the robot, builds a PhysicalHAL from it and drives it 10 cm', async () => {
  expect(blocks).toHaveLength(1);
  const id = `cube-readme-${randomBytes(4).toString('hex')}`;
  const emulator = await startEmulator({ deviceId: id, pty: false });
  const ready = emulator.events.find((e) => e.event === 'ready')!;
  const mdns = ready['mdns'] as { port: number; txt: Record<string, string> };
  const announcer = await discovery.announceRobot({ port: mdns.port, txt: mdns.txt });
  try {
    const body = blocks[0]!
      .replaceAll('console.log(', 'log(')
      .replaceAll("'cube-a1b2c3'", JSON.stringify(id));
    const lines: unknown[][] = [];
    await runDocExample(
      body,
      { '@hal/discovery': discovery },
      { log: (...values: unknown[]) => lines.push(values) },
    );
    expect(lines).toContainEqual([
      id,
      expect.any(Array),
      emulator.udpPort,
      'none',
      expect.arrayContaining(['locomotion.differential:v1.0']),
    ]);
    const last = lines.at(-1)!;
    expect(last[0]).toBe(true);
    expect(last[1]).toBeCloseTo(0.1, 2);
  } finally {
    await announcer.stop();
    await emulator.stop();
  }
}, 30_000);
