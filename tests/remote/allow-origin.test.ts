// `hal serve --sim --ws-port` as users run it (scripts/hal.js, the bundled CLI): without a token
// its WebSocket door refuses a page from another site (HTTP 403, said on stderr too), lets in a
// program and a page from this machine, and `--allow-origin` trusts a named site.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { afterEach, describe, expect, it } from 'vitest';
import { knock } from './knock.js';
import { startServe, stopAllServes, untilMatches } from './serve-command.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const FOREIGN = 'http://evil.example';

afterEach(stopAllServes);

describe('hal serve --ws-port without a token, from the launcher', () => {
  it('refuses a page from another site, and lets in a program and a page from this machine', async () => {
    let stderr = '';
    const url = await startServe(['--sim'], {}, { launcher: true, onStderr: (t) => (stderr += t) });
    const refused = await knock(url, { origin: FOREIGN });
    expect(refused).toMatchObject({ opened: false, status: 403 });
    expect(refused.opened === false && refused.body).toMatch(
      /--allow-origin http:\/\/evil\.example/,
    );
    await untilMatches(
      () => stderr,
      /refused a connection \(HTTP 403\): Origin "http:\/\/evil\.example"/,
    );
    // the refused page took nothing: the program that comes next controls the robot
    expect(await knock(url)).toEqual({ opened: true, role: 'controller' });
    expect(await knock(url, { origin: 'http://localhost:5173' })).toMatchObject({ opened: true });
  });

  it('lets in the origin given with --allow-origin (and still refuses others)', async () => {
    const url = await startServe(
      ['--sim', '--allow-origin', 'https://app.example', '--allow-origin', FOREIGN],
      {},
      {
        launcher: true,
      },
    );
    expect(await knock(url, { origin: FOREIGN })).toEqual({ opened: true, role: 'controller' });
    expect(await knock(url, { origin: 'https://app.example' })).toMatchObject({ opened: true });
    expect(await knock(url, { origin: 'https://other.example' })).toMatchObject({
      opened: false,
      status: 403,
    });
  });

  it('refuses an --allow-origin that is not an origin, or without --ws-port, as a usage error', () => {
    for (const args of [
      ['serve', '--sim', '--ws-port', '0', '--allow-origin', 'app.example'],
      ['serve', '--sim', '--nats', 'nats://127.0.0.1:1', '--allow-origin', FOREIGN],
    ]) {
      const run = spawnSync(process.execPath, ['scripts/hal.js', ...args], {
        cwd: root,
        encoding: 'utf8',
        timeout: 60_000,
      });
      expect(run.status, run.stderr).toBe(2);
      expect(run.stderr).toMatch(/"--allow-origin" (must be an origin|needs --ws-port)/);
    }
  });
});
