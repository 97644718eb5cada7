// Starts the firmware's cube-emulator (built by `bash firmware/scripts/test.sh`) for a test, and
// makes sure it dies with the test: killed on stop(), on afterAll, and when this process exits
// (it also exits by itself when its standard input closes).
import { spawn } from 'node:child_process';
import type { ChildProcess } from 'node:child_process';
import { existsSync } from 'node:fs';
import { builtEmulatorPath } from '@hal/cli/emulator';
import { readEventLines } from './event-lines.js';

/** The emulator binary: `$CUBE_BUILD_DIR/cube-emulator` when that is set (as for test.sh). */
export const EMULATOR_PATH = builtEmulatorPath();

/** One line the emulator printed. */
export type EmulatorEvent = Record<string, unknown> & { event: string };

/**
 * The robot's longest host timeout (`--host-timeout-ms`'s upper bound), for a time-scaled test
 * that is not about the timeout: its window is then this / timeScale of real time (500 ms at
 * x20), which a heartbeat held back on a loaded machine does not outlast.
 */
export const LONGEST_HOST_TIMEOUT_MS = 10_000;

export interface EmulatorOptions {
  timeScale?: number;
  /** Pre-shared key, hex. */
  key?: string;
  hostTimeoutMs?: number;
  deviceId?: string;
  pty?: boolean;
  /** UDP port; default a free one. */
  udpPort?: number;
}

export interface Emulator {
  /** The emulator's process id (its memory is in /proc/PID/status). */
  pid: number;
  udpPort: number;
  /** The pseudo-terminal the serial link listens on ('' with pty: false). */
  pty: string;
  /** Every event printed so far. */
  events: EmulatorEvent[];
  /** Waits for an event that matches, up to `timeoutMs`. */
  waitFor(match: (e: EmulatorEvent) => boolean, timeoutMs?: number): Promise<EmulatorEvent>;
  /** Waits until `count` events match and returns them all (see EventLines.waitForCount). */
  waitForCount(
    match: (e: EmulatorEvent) => boolean,
    count: number,
    timeoutMs?: number,
  ): Promise<EmulatorEvent[]>;
  stop(): Promise<void>;
  /** Kills it at once (SIGKILL), as a power cut or a crash would: it prints nothing more. */
  kill(): Promise<void>;
}

const running = new Set<ChildProcess>();
process.on('exit', () => {
  for (const child of running) child.kill('SIGKILL');
});

/** Kills every emulator still running (for afterAll). */
export async function stopAllEmulators(): Promise<void> {
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

export function requireEmulator(): void {
  if (!existsSync(EMULATOR_PATH)) {
    throw new Error(
      `cube-emulator not found at ${EMULATOR_PATH}: build it with "bash firmware/scripts/test.sh" (the root "pnpm test" does)`,
    );
  }
}

export async function startEmulator(options: EmulatorOptions = {}): Promise<Emulator> {
  requireEmulator();
  const args = ['--udp-port', String(options.udpPort ?? 0), '--exit-on-stdin-eof'];
  if (options.timeScale !== undefined) args.push('--time-scale', String(options.timeScale));
  if (options.key !== undefined) args.push('--key', options.key);
  if (options.hostTimeoutMs !== undefined)
    args.push('--host-timeout-ms', String(options.hostTimeoutMs));
  if (options.deviceId !== undefined) args.push('--device-id', options.deviceId);
  if (options.pty === false) args.push('--no-pty');
  const child = spawn(EMULATOR_PATH, args, { stdio: ['pipe', 'pipe', 'pipe'] });
  running.add(child);
  const { events, waitFor, waitForCount } = readEventLines<EmulatorEvent>(
    child,
    'cube-emulator',
    10_000,
  );
  const exited = new Promise<void>((resolve) => child.once('exit', () => resolve()));
  child.once('exit', () => running.delete(child));

  const ready = await waitFor((e) => e.event === 'ready');
  return {
    pid: child.pid!,
    udpPort: Number(ready['udp_port']),
    pty: String(ready['pty']),
    events,
    waitFor,
    waitForCount,
    stop: async () => {
      if (child.exitCode === null && child.signalCode === null) {
        child.kill('SIGTERM');
        const timer = setTimeout(() => child.kill('SIGKILL'), 2000);
        await exited;
        clearTimeout(timer);
      }
    },
    kill: async () => {
      if (child.exitCode === null && child.signalCode === null) {
        child.kill('SIGKILL');
        await exited;
      }
    },
  };
}
