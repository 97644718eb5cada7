// Runs a host program (a script in ./processes) in its own Node process, from source, as a user
// would run one: `node --conditions=@hal/source --import tsx script.ts args...`. The script
// reports on stdout, one JSON object per line; the process is killed when the test ends.
import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { readEventLines } from './event-lines.js';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));

/** One line a host process printed. */
export type HostEvent = Record<string, unknown> & { event: string };

export interface HostProcess {
  pid: number;
  events: HostEvent[];
  /** Waits for an event that matches, up to `timeoutMs`; rejects if the process exits first. */
  waitFor(match: (e: HostEvent) => boolean, timeoutMs?: number): Promise<HostEvent>;
  /** Resolves with the exit code (or signal) once the process has exited. */
  exited: Promise<number | string>;
  /** Sends a signal (default SIGKILL) and waits for the process to exit. */
  kill(signal?: NodeJS.Signals): Promise<void>;
}

const running = new Set<ChildProcess>();
process.on('exit', () => {
  for (const child of running) child.kill('SIGKILL');
});

/** Starts `processes/<script>` with the given arguments (and extra Node flags). */
export function startHostProcess(
  script: string,
  args: string[],
  nodeFlags: string[] = [],
): HostProcess {
  const path = fileURLToPath(new URL(`./processes/${script}`, import.meta.url));
  const child = spawn(
    process.execPath,
    [...nodeFlags, '--conditions=@hal/source', '--import', 'tsx', path, ...args],
    { cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe'] },
  );
  running.add(child);
  const { events, waitFor } = readEventLines<HostEvent>(child, script, 20_000);
  const exited = new Promise<number | string>((resolve) =>
    child.once('exit', (code, signal) => {
      running.delete(child);
      resolve(code ?? signal ?? 'unknown');
    }),
  );
  return {
    pid: child.pid!,
    events,
    waitFor,
    exited,
    kill: async (signal = 'SIGKILL') => {
      if (child.exitCode === null && child.signalCode === null) child.kill(signal);
      await exited;
    },
  };
}

/** Kills every host process still running (for afterAll). */
export async function stopAllHostProcesses(): Promise<void> {
  await Promise.all(
    [...running].map(
      (child) =>
        new Promise<void>((resolve) => {
          if (child.exitCode !== null || child.signalCode !== null) {
            resolve();
            return;
          }
          child.once('exit', () => resolve());
          child.kill('SIGKILL');
        }),
    ),
  );
}
