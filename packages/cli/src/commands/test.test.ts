import { createServer } from 'node:net';
import { describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';

/** A 127.0.0.1 port nothing listens on. */
async function closedPort(): Promise<number> {
  return new Promise((resolve) => {
    const server = createServer();
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const port = typeof address === 'object' && address !== null ? address.port : 0;
      server.close(() => resolve(port));
    });
  });
}

describe('hal test', () => {
  it('refuses a suite other than "hal" as a usage error', async () => {
    const io = captureIO();
    expect(await runHal(['test', 'robot', '--nats', 'nats://127.0.0.1:1'], io)).toBe(2);
    expect(io.stderr()).toContain('hal: USAGE: hal test knows one suite, "hal"');
  });

  it('refuses an unknown capability, a bad sample count and a bad judge before connecting', async () => {
    for (const [argv, text] of [
      [['--capability', 'motor.warp'], '"--capability" is one of system, motor.differential'],
      [['--samples', '0'], '"--samples" must be an integer in 1..10000, got "0"'],
      [['--samples', 'NaN'], '"--samples" must be an integer in 1..10000, got "NaN"'],
      [['--judge', 'p75'], '"--judge" is p50 or p99'],
      [['--device', 'cube.01'], 'a device id is 1-64 letters'],
    ] as const) {
      const io = captureIO();
      expect(await runHal(['test', 'hal', ...argv], io), argv.join(' ')).toBe(2);
      expect(io.stderr()).toContain(text);
    }
  });

  it(
    'fails with a clear error, and does not hang, when no NATS server answers',
    { timeout: 20_000 },
    async () => {
      const io = captureIO();
      const port = await closedPort();
      expect(
        await runHal(['--json', 'test', 'hal', '--nats', `nats://127.0.0.1:${port}`], io),
      ).toBe(1);
      const error = JSON.parse(io.stderr().trim().split('\n').at(-1) ?? '{}') as {
        error?: { code?: string };
      };
      expect(error.error?.code).toBe('NOT_CONNECTED');
    },
  );

  it('lists the command and its options in the help', async () => {
    const io = captureIO();
    expect(await runHal(['test', '--help'], io)).toBe(0);
    expect(io.stdout()).toContain('--capability <name>');
    expect(io.stdout()).toContain('--device <id>');
    expect(io.stdout()).toContain('--nats <servers>');
  });
});
