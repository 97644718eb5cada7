// The package README's example, run as written against the emulator in real time (only the
// address changes).
import { readFileSync } from 'node:fs';
import { HybridHAL } from '@hal/hybrid';
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';

afterAll(stopAllEmulators);

const readme = readFileSync(new URL('../../packages/hybrid/README.md', import.meta.url), 'utf8');
const blocks = [...readme.matchAll(/```ts\n([\s\S]*?)```/g)].map((m) => m[1]!);

type Example = (
  hybrid: typeof HybridHAL,
  physical: typeof PhysicalHAL,
  simulation: typeof SimulationHAL,
  log: (...values: unknown[]) => void,
) => Promise<void>;

/** Turns the README block into a function: drops the imports, routes console.log to `log`. */
function compile(block: string, replacements: Array<[string, string]>): Example {
  let body = block.replace(/^import .*$/gm, '').replaceAll('console.log(', 'log(');
  for (const [from, to] of replacements) {
    expect(body).toContain(from);
    body = body.replaceAll(from, to);
  }
  const AsyncFunction = Object.getPrototypeOf(async () => undefined).constructor as new (
    ...args: string[]
  ) => Example;
  return new AsyncFunction('HybridHAL', 'PhysicalHAL', 'SimulationHAL', 'log', body);
}

describe('the @hal/hybrid README', () => {
  it('drives the emulated robot and its twin 10 cm and prints the result and the divergence', async () => {
    expect(blocks).toHaveLength(1);
    const emulator = await startEmulator({ pty: false });
    const logged: unknown[][] = [];
    try {
      const example = compile(blocks[0]!, [
        ["'192.168.4.1'", "'127.0.0.1'"],
        ['udpPort: 4210', `udpPort: ${emulator.udpPort}`],
      ]);
      await example(HybridHAL, PhysicalHAL, SimulationHAL, (...values) => logged.push(values));
      expect(logged).toHaveLength(1);
      expect(logged[0]?.[0]).toBe(true);
      expect(logged[0]?.[1]).toEqual({ success: true });
      expect(logged[0]?.[2]).toMatchObject({ exceeded: false, positionM: expect.any(Number) });
      expect(emulator.events.filter((e) => e.event === 'move_finished')).toHaveLength(1);
    } finally {
      await emulator.stop();
    }
  });
});
