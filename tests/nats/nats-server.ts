// Starts Debian's nats-server (installed by scripts/setup.sh) on a free 127.0.0.1 port for a
// test or a benchmark, and makes sure it dies with it: killed on stop(), on afterAll
// (stopAllNatsServers) and when this process exits. Every wait is bounded.
import { spawn, spawnSync } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const running = new Set<ChildProcess>();
process.on('exit', () => {
  for (const child of running) child.kill('SIGKILL');
});

/** The nats-server executable on PATH (Debian installs it in /usr/sbin). */
export function natsServerPath(): string {
  for (const candidate of ['nats-server', '/usr/sbin/nats-server']) {
    if (spawnSync(candidate, ['--version']).status === 0) return candidate;
  }
  throw new Error(
    'nats-server not found: install it with scripts/setup.sh (Debian package nats-server)',
  );
}

/** A free TCP port on 127.0.0.1. */
export async function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const port = typeof address === 'object' && address !== null ? address.port : 0;
      server.close(() => resolve(port));
    });
  });
}

export interface NatsServerOptions {
  /** Require this user and password (written to a config file in a temp directory). */
  auth?: { user: string; password: string };
  /** Port; default a free one. */
  port?: number;
}

export interface NatsServer {
  port: number;
  /** `nats://127.0.0.1:PORT`. */
  url: string;
  stop(): Promise<void>;
  /** Kills the server and starts a new one on the same port, as an operator's restart would. */
  restart(): Promise<void>;
}

function launch(args: string[], timeoutMs: number): Promise<ChildProcess> {
  const child = spawn(natsServerPath(), args, { stdio: ['ignore', 'ignore', 'pipe'] });
  running.add(child);
  child.once('exit', () => running.delete(child));
  return new Promise((resolve, reject) => {
    let output = '';
    const timer = setTimeout(() => {
      child.kill('SIGKILL');
      reject(new Error(`nats-server not ready within ${timeoutMs} ms: ${output}`));
    }, timeoutMs);
    child.stderr?.on('data', (chunk: Buffer) => {
      output += chunk.toString();
      if (output.includes('Server is ready')) {
        clearTimeout(timer);
        resolve(child);
      }
    });
    child.once('exit', (code, signal) => {
      clearTimeout(timer);
      reject(new Error(`nats-server exited (${code ?? signal}): ${output}`));
    });
  });
}

function kill(child: ChildProcess): Promise<void> {
  return new Promise((resolve) => {
    if (child.exitCode !== null || child.signalCode !== null) {
      resolve();
      return;
    }
    child.once('exit', () => resolve());
    child.kill('SIGKILL');
  });
}

export async function startNatsServer(options: NatsServerOptions = {}): Promise<NatsServer> {
  const port = options.port ?? (await freePort());
  const args = ['-a', '127.0.0.1', '-p', String(port)];
  if (options.auth !== undefined) {
    const dir = mkdtempSync(join(tmpdir(), 'hal-nats-'));
    const config = join(dir, 'nats.conf');
    const { user, password } = options.auth;
    writeFileSync(
      config,
      `authorization {\n  users = [ { user: ${JSON.stringify(user)}, password: ${JSON.stringify(password)} } ]\n}\n`,
    );
    args.push('-c', config);
  }
  let child = await launch(args, 10_000);
  return {
    port,
    url: `nats://127.0.0.1:${port}`,
    stop: () => kill(child),
    restart: async () => {
      await kill(child);
      // The port is free again once the old process is gone; retry briefly if it is not yet.
      for (let attempt = 0; ; attempt += 1) {
        try {
          child = await launch(args, 10_000);
          return;
        } catch (error) {
          if (attempt >= 10) throw error;
          await new Promise((resolve) => setTimeout(resolve, 100));
        }
      }
    },
  };
}

/** Kills every server still running (for afterAll). */
export async function stopAllNatsServers(): Promise<void> {
  await Promise.all([...running].map(kill));
}
