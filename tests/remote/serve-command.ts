// Starts `hal serve --ws-port 0` as a user runs it, and makes sure it dies with the test.
import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';

const CLI = fileURLToPath(new URL('../../packages/cli/src/main.ts', import.meta.url));
/** `hal` of a checkout as users run it (`pnpm hal`): the bundled CLI. */
const LAUNCHER = fileURLToPath(new URL('../../scripts/hal.js', import.meta.url));
const running = new Set<ChildProcess>();
process.on('exit', () => {
  for (const child of running) child.kill('SIGKILL');
});

/**
 * Starts `hal serve` on WebSocket on a free port (from the sources, or with `launcher` as
 * `scripts/hal.js`); resolves with its URL once it prints `listening`, or rejects with its stderr
 * (and `exitCode`) when it exits first. `onStderr` sees what it writes there.
 */
export function startServe(
  args: string[],
  env: Record<string, string> = {},
  { launcher = false, onStderr }: { launcher?: boolean; onStderr?: (text: string) => void } = {},
): Promise<string> {
  const hal = launcher ? [LAUNCHER] : ['--conditions=@hal/source', '--import', 'tsx', CLI];
  const child = spawn(process.execPath, [...hal, 'serve', '--ws-port', '0', ...args], {
    stdio: ['ignore', 'pipe', 'pipe'],
    env: { ...process.env, ...env },
  });
  running.add(child);
  child.once('exit', () => running.delete(child));
  let stderr = '';
  child.stderr.on('data', (chunk: Buffer) => {
    stderr += chunk.toString();
    onStderr?.(chunk.toString());
  });
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`hal serve did not start: ${stderr}`)), 30_000);
    createInterface({ input: child.stdout }).on('line', (line) => {
      const match = /^\s*listening (ws:\/\/\S+)/.exec(line);
      if (match !== null) {
        clearTimeout(timer);
        resolve(match[1]!);
      }
    });
    child.once('exit', (code) => {
      clearTimeout(timer);
      reject(Object.assign(new Error(stderr), { exitCode: code }));
    });
  });
}

/** Stops every `hal serve` still running (SIGTERM: it stops the robot and exits). */
export function stopAllServes(): void {
  for (const child of running) child.kill('SIGTERM');
}

/** Waits (up to `timeoutMs`) for `text()`, read again every 50 ms, to match `pattern`. */
export async function untilMatches(
  text: () => string,
  pattern: RegExp,
  timeoutMs = 10_000,
): Promise<void> {
  for (let waited = 0; !pattern.test(text()); waited += 50) {
    if (waited >= timeoutMs)
      throw new Error(`never matched ${pattern} in ${timeoutMs} ms: ${text()}`);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
}
