// The package README's example, run as written against the emulator in real time (only the
// address changes).
import { readFileSync } from 'node:fs';
import * as hybrid from '@hal/hybrid';
import * as physical from '@hal/physical';
import * as simulation from '@hal/simulation';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';

afterAll(stopAllEmulators);

const readme = readFileSync(new URL('../../packages/hybrid/README.md', import.meta.url), 'utf8');
const blocks = fencedBlocks(readme, 'ts');

const MODULES = { '@hal/hybrid': hybrid, '@hal/physical': physical, '@hal/simulation': simulation };

describe('the @hal/hybrid README', () => {
  it('drives the emulated robot and its twin 10 cm and prints the result and the divergence', async () => {
    expect(blocks).toHaveLength(1);
    const emulator = await startEmulator({ pty: false });
    const logged: unknown[][] = [];
    try {
      let code = blocks[0]!.replaceAll('console.log(', 'log(');
      for (const [from, to] of [
        ["'192.168.4.1'", "'127.0.0.1'"],
        ['udpPort: 4210', `udpPort: ${emulator.udpPort}`],
      ] as const) {
        expect(code).toContain(from);
        code = code.replaceAll(from, to);
      }
      await runDocExample(code, MODULES, { log: (...values: unknown[]) => logged.push(values) });
      expect(logged).toHaveLength(1);
      expect(logged[0]?.[0]).toBe(true);
      expect(logged[0]?.[1]).toEqual({ success: true });
      expect(logged[0]?.[2]).toMatchObject({ exceeded: false, positionM: expect.any(Number) });
      expect(await emulator.waitForCount((e) => e.event === 'move_finished', 1)).toHaveLength(1);
    } finally {
      await emulator.stop();
    }
  });
});
