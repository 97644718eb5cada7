// The package README's examples, run as written against the emulator in real time (only the
// address changes).
import { readFileSync } from 'node:fs';
import * as physical from '@hal/physical';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';

afterAll(stopAllEmulators);

const readme = readFileSync(new URL('../../packages/physical/README.md', import.meta.url), 'utf8');
const blocks = fencedBlocks(readme, 'ts');

/** Runs a README block as written but for `replacements` (each must be there), console.log to `log`. */
async function runExample(
  block: string,
  replacements: Array<[string, string]>,
  log: (...values: unknown[]) => void,
): Promise<void> {
  let code = block.replaceAll('console.log(', 'log(');
  for (const [from, to] of replacements) {
    expect(code).toContain(from);
    code = code.replaceAll(from, to);
  }
  await runDocExample(code, { '@hal/physical': physical }, { log });
}

describe('the @hal/physical README', () => {
  it('has the two connection examples', () => {
    expect(blocks).toHaveLength(2);
  });

  it('connects by IP, moves 10 cm and prints the pose', async () => {
    const emulator = await startEmulator({ pty: false });
    const logged: unknown[][] = [];
    try {
      await runExample(
        blocks[0]!,
        [
          ["'192.168.4.1'", "'127.0.0.1'"],
          ['udpPort: 4210', `udpPort: ${emulator.udpPort}`],
        ],
        (...values) => logged.push(values),
      );
      expect(logged[0]?.[0]).toBe(true);
      expect(logged[0]?.[1]).toMatchObject({
        position: { x: expect.closeTo(0.1, 3) },
        confirmed: true,
      });
      expect(await emulator.waitForCount((e) => e.event === 'move_finished', 1)).toHaveLength(1);
    } finally {
      await emulator.stop();
    }
  });

  it('connects by serial port and turns 90 degrees', async () => {
    const emulator = await startEmulator();
    const logged: unknown[][] = [];
    try {
      await runExample(blocks[1]!, [["'/dev/ttyUSB0'", `'${emulator.pty}'`]], (...values) =>
        logged.push(values),
      );
      expect(logged).toEqual([[true]]);
      const finished = await emulator.waitFor((e) => e.event === 'move_finished');
      expect(finished).toMatchObject({ left_steps: -1706, right_steps: 1706 });
    } finally {
      await emulator.stop();
    }
  });
});
