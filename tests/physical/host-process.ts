// Runs a host program (a script in ./processes) in its own Node process, from source, as a user
// would run one: `node --conditions=@hal/source --import tsx script.ts args...`. The script
// reports on stdout, one JSON object per line; the process is killed when the test ends.
import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { createInterface } from 'node:readline';

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
  const events: HostEvent[] = [];
  const waiters = new Set<() => void>();
  let stderr = '';
  child.stderr.on('data', (chunk: Buffer) => {
    stderr += chunk.toString();
  });
  createInterface({ input: child.stdout }).on('line', (line) => {
    try {
      events.push(JSON.parse(line) as HostEvent);
    } catch {
      events.push({ event: 'unparsed', line });
    }
    for (const wake of waiters) wake();
  });
  const exited = new Promise<number | string>((resolve) =>
    child.once('exit', (code, signal) => {
      running.delete(child);
      resolve(code ?? signal ?? 'unknown');
      for (const wake of waiters) wake();
    }),
  );
  const waitFor = (match: (e: HostEvent) => boolean, timeoutMs = 20_000) =>
    new Promise<HostEvent>((resolve, reject) => {
      const check = () => {
        const found = events.find(match);
        if (found !== undefined) {
          done();
          resolve(found);
        } else if (child.exitCode !== null || child.signalCode !== null) {
          done();
          reject(new Error(`${script} exited (${child.exitCode ?? child.signalCode}): ${stderr}`));
        }
      };
      const timer = setTimeout(() => {
        done();
        reject(new Error(`${script}: no matching event within ${timeoutMs} ms: ${stderr}`));
      }, timeoutMs);
      const done = () => {
        clearTimeout(timer);
        waiters.delete(check);
      };
      waiters.add(check);
      check();
    });
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
