// A documented block in a network of its own: it has 127.0.0.1:4222 to itself while the machine's
// 4222 is taken (as by the README's `nats-server -a 127.0.0.1 &`), and it talks to its own
// nats-server there, not to what the machine runs.
import { spawn } from 'node:child_process';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { natsServerPath } from '../nats/nats-server.js';
import { blockNetwork } from './block-network.js';
import { blockScript } from './block-script.js';
import { holdPorts } from './held-ports.js';
import type { HeldPorts } from './held-ports.js';

const network = blockNetwork();
let held: HeldPorts | undefined;

beforeAll(async () => {
  held = await holdPorts([4222]);
});
afterAll(async () => {
  await held?.release();
});

/** Runs `text` as a documented block, the way doc-commands.test.ts does; bounded to 30 s. */
function run(text: string): Promise<{ code: number | null; output: string }> {
  const script = blockScript({ language: 'sh', text }, { natsServer: natsServerPath() });
  const { file, args } = network.command(script);
  return new Promise((resolve) => {
    const child = spawn(file, args, { detached: true });
    let output = '';
    child.stdout.on('data', (chunk: Buffer) => (output += chunk.toString()));
    child.stderr.on('data', (chunk: Buffer) => (output += chunk.toString()));
    const timer = setTimeout(() => {
      output += '\n(killed after 30 s)';
      if (child.pid !== undefined) process.kill(-child.pid, 'SIGKILL');
    }, 30_000);
    child.once('close', (code) => {
      clearTimeout(timer);
      resolve({ code, output });
    });
  });
}

describe('a block in a network of its own', () => {
  it('reaches its own nats-server on 4222 while the machine has 4222 taken', async () => {
    if (!network.own) {
      // a machine without namespaces runs the blocks on its own network: the test says why
      expect(network.reason).toMatch(/\S/);
      expect(network.command('true')).toEqual({ file: 'bash', args: ['-c', 'true'] });
      return;
    }
    const { code, output } = await run(
      // bash's /dev/tcp: the NATS server greets a client with its INFO line
      'head -c 4 < /dev/tcp/127.0.0.1/4222   # the server of nats://127.0.0.1:4222',
    );
    expect(code, output).toBe(0);
    expect(output).toMatch(/doc-test: nats-server is ready\nINFO/);
  });

  it('has its ports to itself: two blocks bind the same one at once', async () => {
    const bind = `node -e "require('net').createServer().listen(8765, '127.0.0.1', function () { setTimeout(() => this.close(), 1500) })"`;
    const codes = (await Promise.all([run(bind), run(bind)])).map((r) => r.code);
    // on the machine's one network the second bind fails: doc-commands runs them one at a time
    expect(codes.filter((code) => code === 0)).toHaveLength(network.own ? 2 : 1);
  });
});
