// The `hal` program as a child process: its help, a refusal without a terminal, and a robot that
// is not there, each with the exit code a script sees.
import { spawnSync } from 'node:child_process';
import { describe, expect, it } from 'vitest';
import { HAL_MAIN, runHalProcess } from '../helpers/hal-process.js';

describe('the hal program', () => {
  it('lists status, drive, teleop and serve in its help', async () => {
    const run = await runHalProcess(['--help']);
    expect(run.code).toBe(0);
    for (const command of ['status', 'drive', 'teleop', 'serve']) {
      expect(run.stdout).toMatch(new RegExp(`^  ${command} `, 'm'));
    }
  });

  it('refuses teleop when its standard input is a pipe, before touching a robot', async () => {
    const run = await runHalProcess(['teleop', '--udp', '127.0.0.1:9']);
    expect(run.code).toBe(2);
    expect(run.stderr).toBe(
      'hal: USAGE: hal teleop reads the keyboard: run it in a terminal (its standard input is not a TTY)\n',
    );
  });

  it('exits 1 with NOT_CONNECTED when no robot answers, within the connect timeout', async () => {
    const started = Date.now();
    const run = await runHalProcess([
      'status',
      '--udp',
      '127.0.0.1:9',
      '--connect-timeout',
      '1000',
    ]);
    expect(run.code).toBe(1);
    expect(run.stderr).toBe(
      'hal: NOT_CONNECTED: no answer from the robot at udp 127.0.0.1:9 within 1000 ms: nothing came back. Is it powered, on this network, at this address and port? (A wrong --key is answered with AUTH_FAILED: silence is not a key problem.)\n',
    );
    expect(Date.now() - started).toBeLessThan(15_000); // process start-up included: it did not hang
  });

  it('stops cleanly when the program reading its output goes away (hal status --watch | head)', () => {
    const hal = `"${process.execPath}" --conditions=@hal/source --import tsx "${HAL_MAIN}"`;
    const run = spawnSync(
      'bash',
      [
        '-c',
        `${hal} status --sim --watch --rate 20 | head -n 2 >/dev/null; echo "exit=\${PIPESTATUS[0]}"`,
      ],
      { encoding: 'utf8', timeout: 30_000 },
    );
    expect(run.status).toBe(0);
    expect(run.stdout).toBe('exit=0\n');
    expect(run.stderr).not.toMatch(/EPIPE|Unhandled|throw/);
  });
});
