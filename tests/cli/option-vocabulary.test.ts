// The CLI's one option vocabulary, through the launcher users run (`node scripts/hal.js`): bad
// values and output places that cannot be written are usage errors (exit 2) naming the option,
// before any robot is touched or trial run; distances read the same in every command; a port in
// use names the option that changes it.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import type { AddressInfo, Server } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { HAL_LAUNCHER, runHalProcess } from '../helpers/hal-process.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-options-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** `hal args` through the checkout's launcher, killed after 60 s (nothing here may hang). */
const hal = (...args: string[]) => runHalProcess(args, 60_000, HAL_LAUNCHER);

/** A TCP port something already listens on. */
async function takenPort(): Promise<{ port: number; server: Server }> {
  const server = createServer();
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { port: (server.address() as AddressInfo).port, server };
}

beforeAll(async () => {
  // the launcher bundles the CLI on its first run: once, before the runs below
  expect((await runHalProcess(['--version'], 150_000, HAL_LAUNCHER)).code).toBe(0);
}, 160_000);

describe('usage errors exit 2 in every command, naming the option', () => {
  it.each([
    [['mcp', '--http', '--port', '99999'], '"--port" must be an integer in 0..65535, got "99999"'],
    [
      ['agent', '--sim', '--base-url', 'notaurl', '--model', 'm', 'drive'],
      '"--base-url" must be a http:// or https:// URL, got "notaurl"',
    ],
    [
      ['eval', '--agent', 'openai:m', '--base-url', 'notaurl'],
      '"--base-url" must be a http:// or https:// URL, got "notaurl"',
    ],
    [['emulate', '--key', 'abc'], '"--key" must be 1..64 bytes written as hex'],
    [
      ['eval', '--on', 'udp://10.0.0.1', '--key', 'xyz'],
      '"--key" must be 1..64 bytes written as hex',
    ],
    [['eval', '--loss', '2'], '"--loss" must be a number in 0..0.9, got "2"'],
    [
      ['fleet', 'health', '--discover-ms', 'soon'],
      '"--discover-ms" must be an integer in 1..600000',
    ],
    [['drive', 'forward', '3deg', '--sim'], '"distance" must be a distance'],
    [
      ['record', '-o', 'x.mcap', '--sim', 'turn 90cm'],
      'step "turn 90cm": the angle must be an angle',
    ],
    [['nosuch', '--help'], "unknown command 'nosuch'"],
  ])(
    'hal %j',
    async (args, message) => {
      const run = await hal(...args);
      expect(run.code, run.stderr).toBe(2);
      expect(run.stderr).toContain(`hal: USAGE: ${message}`);
      expect(run.stdout).not.toContain('Usage: hal');
    },
    60_000,
  );
});

describe('output places are checked before the robot or the first trial', () => {
  it('refuses a recording whose folder is missing, or on /proc, at once (exit 2)', async () => {
    for (const file of [join(dir, 'no-such-dir', 'x.mcap'), '/proc/x.mcap']) {
      const run = await hal('record', '-o', file, '--sim', 'forward 0.01');
      expect(run.code, run.stderr).toBe(2);
      expect(run.stderr).toContain(`hal: USAGE: "-o" ${file}: `);
      expect(run.stdout).toBe('');
    }
  }, 60_000);

  it('keeps a recording that exists unless --overwrite, then replaces it', async () => {
    const file = join(dir, 'run.mcap');
    writeFileSync(file, 'an earlier run');
    const refused = await hal('record', '-o', file, '--sim', 'forward 1cm');
    expect(refused.code, refused.stderr).toBe(2);
    expect(refused.stderr).toContain(
      `hal: USAGE: "-o" ${file}: exists (give --overwrite to replace it)`,
    );
    expect(readFileSync(file, 'utf8')).toBe('an earlier run');
    const replaced = await hal(
      '--json',
      'record',
      '-o',
      file,
      '--overwrite',
      '--sim',
      '--time-scale',
      '20',
      'forward 1cm',
    );
    expect(replaced.code, replaced.stderr).toBe(0);
    expect(readFileSync(file).subarray(1, 5).toString()).toBe('MCAP');
  }, 60_000);

  it('refuses hal eval --out where it cannot write, before any trial (a file there, /proc)', async () => {
    const file = join(dir, 'eval-out');
    writeFileSync(file, 'not a folder');
    for (const [option, place, why] of [
      ['--out', file, 'exists and is not a folder'],
      ['--out', '/proc/eval', 'is on the proc filesystem'],
      ['--record', '/proc/trials', 'is on the proc filesystem'],
    ] as const) {
      const run = await hal('eval', '--agent', 'oracle', '--trials', '1', option, place);
      expect(run.code, run.stderr).toBe(2);
      expect(run.stderr).toContain(`hal: USAGE: "${option}" ${place}: ${why}`);
      expect(run.stderr).not.toMatch(/\d+\/\d+ oracle/); // no trial ran
    }
  }, 60_000);
});

describe('the same words mean the same in every command', () => {
  it('drives a distance given with its unit as the metres a bare number means', async () => {
    const run = await hal('--json', 'drive', 'forward', '3cm', '--sim', '--time-scale', '20');
    expect(run.code, run.stderr).toBe(0);
    const outcome = JSON.parse(run.stdout.split('\n')[0]!) as {
      action: { metres: number };
      pose: { position: { x: number } };
    };
    expect(outcome.action.metres).toBe(0.03);
    expect(outcome.pose.position.x).toBeCloseTo(0.03, 3);
  }, 60_000);

  it('takes [IPV6]:PORT for a robot, as a robot to connect to and not a usage error', async () => {
    const run = await hal('status', '--udp', '[::1]:9', '--connect-timeout', '300');
    expect(run.code, run.stderr).toBe(1);
    expect(run.stderr).not.toContain('USAGE');
    expect(run.stderr).toContain('[::1]:9');
  }, 60_000);
});

describe('a port in use names the option that changes it', () => {
  it.each([
    [['mcp', '--http'], '--port'],
    [['serve', '--sim'], '--ws-port'],
  ])(
    'hal %j',
    async (args, option) => {
      const { port, server } = await takenPort();
      try {
        const portArgs =
          option === '--port' ? ['--port', String(port)] : ['--ws-port', String(port)];
        const run = await hal(...args, ...portArgs);
        expect(run.code, run.stderr).toBe(1);
        expect(run.stderr).toContain(
          `hal: FAILED: port ${port} is in use (EADDRINUSE); choose another with ${option}`,
        );
      } finally {
        await new Promise((resolve) => server.close(resolve));
      }
    },
    60_000,
  );
});
