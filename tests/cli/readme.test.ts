// The README's `hal` quick start, run as written (the NATS server is one this test starts).
import { readFileSync } from 'node:fs';
import { runHal } from '@hal/cli';
import { afterAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import { captureIO } from './capture-io.js';

const readme = readFileSync(new URL('../../README.md', import.meta.url), 'utf8');
const lines = [...readme.matchAll(/^pnpm hal (.+?)(?:\s+#.*)?$/gm)].map((m) => m[1]!.split(/\s+/));

afterAll(stopAllNatsServers);

describe("the README's hal quick start", () => {
  it('has the four commands: status, drive, serve and status through NATS', () => {
    expect(lines.map((argv) => argv[0])).toEqual(['status', 'drive', 'serve', 'status']);
  });

  it('runs as written', async () => {
    const nats = await startNatsServer();
    const argvs = lines.map((argv) =>
      argv.map((a) => a.replace('nats://127.0.0.1:4222', nats.url)),
    );
    for (const argv of argvs.slice(0, 2)) {
      const io = captureIO();
      expect(await runHal(argv, io), `${argv.join(' ')}: ${io.stderr()}`).toBe(0);
    }
    const serveIo = captureIO();
    const serving = runHal(argvs[2]!, serveIo);
    const deadline = Date.now() + 20_000;
    while (!serveIo.stdout().includes('serving') && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    const status = captureIO();
    expect(await runHal(argvs[3]!, status), status.stderr()).toBe(0);
    expect(status.stdout()).toMatch(/^device {8}sim-1 \(simulation/m);
    serveIo.abort();
    expect(await serving).toBe(0);
  });
});
