// A long-running command of a temporary app (`hal emulate`), read line by line: waits are bounded,
// and the process is stopped and awaited at the end.
import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { join } from 'node:path';
import { createInterface } from 'node:readline';
import { cleanEnv } from './temp-app.js';

export interface AppProcess {
  /** Every line it printed so far, stdout and stderr in order of arrival. */
  readonly lines: string[];
  /** The first line matching `pattern`, waited for at most `timeoutMs`. */
  waitFor(pattern: RegExp, timeoutMs?: number): Promise<string>;
  /** Sends `signal` and resolves with the exit code (SIGKILL after `graceMs`). */
  stop(signal?: NodeJS.Signals, graceMs?: number): Promise<number | null>;
}

/** Starts node_modules/.bin/NAME in the app. */
export function startAppCommand(appDir: string, name: string, args: readonly string[]): AppProcess {
  const child: ChildProcess = spawn(join(appDir, 'node_modules', '.bin', name), [...args], {
    cwd: appDir,
    env: cleanEnv(),
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  const lines: string[] = [];
  const listeners = new Set<() => void>();
  const exited = new Promise<number | null>((resolve) => {
    child.once('exit', (code) => resolve(code));
    child.once('error', () => resolve(null));
  });
  for (const stream of [child.stdout, child.stderr]) {
    createInterface({ input: stream! }).on('line', (line) => {
      lines.push(line);
      for (const listener of listeners) listener();
    });
  }
  return {
    lines,
    waitFor: (pattern, timeoutMs = 20_000) =>
      new Promise<string>((resolve, reject) => {
        const check = () => {
          const found = lines.find((line) => pattern.test(line));
          if (found === undefined) return;
          done();
          resolve(found);
        };
        const timer = setTimeout(() => {
          done();
          reject(
            new Error(`no line matching ${pattern} within ${timeoutMs} ms:\n${lines.join('\n')}`),
          );
        }, timeoutMs);
        const ended = () => {
          done();
          reject(
            new Error(`${name} exited before a line matched ${pattern}:\n${lines.join('\n')}`),
          );
        };
        const done = () => {
          clearTimeout(timer);
          listeners.delete(check);
        };
        listeners.add(check);
        void exited.then(() => {
          if (listeners.has(check)) ended();
        });
        check();
      }),
    stop: async (signal = 'SIGINT', graceMs = 5000) => {
      if (child.exitCode === null && child.signalCode === null) child.kill(signal);
      const timer = setTimeout(() => child.kill('SIGKILL'), graceMs);
      const code = await exited;
      clearTimeout(timer);
      return code;
    },
  };
}
