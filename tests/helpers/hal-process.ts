// Runs the `hal` command as a user runs it: a child process from source (the CLI's main.ts), or
// as another `hal` program when a test says (the checkout's launcher, a packed bin), with every
// wait bounded and every child killed when the test process exits. One helper for every test
// folder that runs `hal` as a process.
import { spawn } from 'node:child_process';
import type { ChildProcessByStdio } from 'node:child_process';
import type { Readable, Writable } from 'node:stream';
import { fileURLToPath } from 'node:url';
import { readEventLines } from '../physical/event-lines.js';
import type { EventLines } from '../physical/event-lines.js';
import { runProcess } from './run-process.js';

/** The CLI's entry, run from source. */
export const HAL_MAIN = fileURLToPath(new URL('../../packages/cli/src/main.ts', import.meta.url));
const MAIN = HAL_MAIN;
/** Node's flags to run the CLI from source. */
const HAL_FLAGS = ['--conditions=@hal/source', '--import', 'tsx'];

/** A way to start `hal`: the program and the arguments that come before hal's own. */
export interface HalCommand {
  command: string;
  args: readonly string[];
  cwd?: string;
  env?: NodeJS.ProcessEnv;
}

/** `hal` from source, through tsx (the default). */
export const HAL_FROM_SOURCE: HalCommand = {
  command: process.execPath,
  args: [...HAL_FLAGS, MAIN],
};

/** `hal` as `pnpm hal` runs it: the checkout's launcher, scripts/hal.js, and its bundle. */
export const HAL_LAUNCHER: HalCommand = {
  command: process.execPath,
  args: [fileURLToPath(new URL('../../scripts/hal.js', import.meta.url))],
};

type Child = ChildProcessByStdio<Writable, Readable, Readable>;
const running = new Set<Child>();
process.on('exit', () => {
  for (const child of running) child.kill('SIGKILL');
});

function spawnHal(args: readonly string[], hal: HalCommand): Child {
  const child = spawn(hal.command, [...hal.args, ...args], {
    cwd: hal.cwd,
    env: hal.env ?? process.env,
    stdio: ['pipe', 'pipe', 'pipe'],
  });
  running.add(child);
  child.once('exit', () => running.delete(child));
  return child;
}

export interface HalRun {
  code: number | null;
  stdout: string;
  stderr: string;
}

/** Runs `hal args` to its end (killed after `timeoutMs`), from source unless `hal` says. */
export async function runHalProcess(
  args: readonly string[],
  timeoutMs = 30_000,
  hal: HalCommand = HAL_FROM_SOURCE,
): Promise<HalRun> {
  const { status, stdout, stderr } = await runProcess(hal.command, [...hal.args, ...args], {
    timeoutMs,
    ...(hal.cwd === undefined ? {} : { cwd: hal.cwd }),
    ...(hal.env === undefined ? {} : { env: hal.env }),
  });
  return { code: status, stdout, stderr };
}

export interface HalProcess<E> extends EventLines<E> {
  /** Resolves with the exit code once it has exited by itself or been stopped. */
  exited: Promise<number | null>;
  /** Sends `signal` (Ctrl-C by default) and resolves the exit code (SIGKILL after `timeoutMs`). */
  stop(signal?: NodeJS.Signals, timeoutMs?: number): Promise<number | null>;
}

/**
 * Starts a long-running `hal --json ...` (serve, emulate, discover) whose stdout is JSON lines,
 * from source unless `hal` says.
 */
export function startHalProcess<E extends { event: string }>(
  args: readonly string[],
  hal: HalCommand = HAL_FROM_SOURCE,
): HalProcess<E> {
  const child = spawnHal(args, hal);
  child.stdin.end();
  const lines = readEventLines<E>(child, `hal ${args.join(' ')}`, 30_000);
  const exited = new Promise<number | null>((resolve) =>
    child.once('exit', (code) => resolve(code)),
  );
  return {
    ...lines,
    exited,
    stop: async (signal = 'SIGINT', timeoutMs = 10_000) => {
      if (child.exitCode !== null || child.signalCode !== null) return child.exitCode;
      child.kill(signal);
      const timer = setTimeout(() => child.kill('SIGKILL'), timeoutMs);
      const code = await exited;
      clearTimeout(timer);
      return code;
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
