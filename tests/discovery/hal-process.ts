// Runs the `hal` command as a user does (node + the CLI's main.ts from source) in a child process,
// reads its --json lines, and makes sure it dies with the test.
import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { readEventLines } from '../physical/event-lines.js';
import type { EventLines } from '../physical/event-lines.js';

const HAL = fileURLToPath(new URL('../../packages/cli/src/main.ts', import.meta.url));

const running = new Set<ChildProcess>();
process.on('exit', () => {
  for (const child of running) child.kill('SIGKILL');
});

export type HalLine = Record<string, unknown> & { event: string };

export interface HalProcess extends EventLines<HalLine> {
  child: ChildProcess;
  /** Resolves with the exit code once it has exited. */
  exited: Promise<number | null>;
  /** Sends SIGINT (Ctrl-C) and waits for the exit; SIGKILL after 10 s. */
  interrupt(): Promise<number | null>;
}

/** Starts `hal --json ...args`. Lines without an `event` field (discover's robots) are kept too. */
export function startHal(args: readonly string[]): HalProcess {
  const child = spawn(
    process.execPath,
    ['--conditions=@hal/source', '--import', 'tsx', HAL, '--json', ...args],
    { stdio: ['ignore', 'pipe', 'pipe'] },
  );
  running.add(child);
  const exited = new Promise<number | null>((resolve) =>
    child.once('exit', (code) => {
      running.delete(child);
      resolve(code);
    }),
  );
  const lines = readEventLines<HalLine>(child, `hal ${args[0] ?? ''}`, 30_000);
  return {
    ...lines,
    child,
    exited,
    interrupt: async () => {
      if (child.exitCode === null && child.signalCode === null) {
        child.kill('SIGINT');
        const timer = setTimeout(() => child.kill('SIGKILL'), 10_000);
        await exited;
        clearTimeout(timer);
      }
      return exited;
    },
  };
}

/** Kills every `hal` child still running (for afterAll). */
export async function stopAllHal(): Promise<void> {
  await Promise.all(
    [...running].map(
      (child) =>
        new Promise<void>((resolve) => {
          child.once('exit', () => resolve());
          child.kill('SIGKILL');
        }),
    ),
  );
}
