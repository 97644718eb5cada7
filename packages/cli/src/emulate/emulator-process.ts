// Runs cube-emulator as a child process: waits (bounded) for its ready line, passes on each
// event line it prints, and stops it with SIGTERM (SIGKILL when it does not exit in time). It is
// started with --exit-on-stdin-eof, so it also ends when `hal` itself dies.
import { spawn } from 'node:child_process';
import { createInterface } from 'node:readline';
import { deadline } from '@hal/types';
import { z } from 'zod';
import { CliError } from '../cli-error.js';

/** The emulator's ready line (docs/firmware.md), as far as `hal emulate` reads it. */
export const ReadyLineSchema = z.object({
  event: z.literal('ready'),
  udp_port: z.number().int().min(1).max(65_535),
  pty: z.string(),
  device_id: z.string(),
  auth: z.string(),
  protocol_version: z.string(),
  mdns: z
    .object({ service: z.string(), port: z.number().int(), txt: z.record(z.string(), z.string()) })
    .nullable()
    .optional(),
});
export type ReadyLine = z.infer<typeof ReadyLineSchema>;

/** The emulator's `wheels` event (with --report-wheels-ms): the wheel positions, steps from boot. */
export const WheelsEventSchema = z.object({
  event: z.literal('wheels'),
  left_position: z.number().int(),
  right_position: z.number().int(),
});

export interface EmulatorProcess {
  ready: ReadyLine;
  /** Resolves when it exits, with how, and what it wrote on stderr. */
  exited: Promise<{ code: number | null; signal: string | null; stderr: string }>;
  /** Stops it (SIGTERM, then SIGKILL after `graceMs`) and resolves once it has exited. */
  stop(graceMs?: number): Promise<void>;
  /** The wheel positions now, steps from boot, where the robot tells them to its own process. */
  wheels?: () => { left: number; right: number };
}

export async function startEmulatorProcess(
  path: string,
  args: readonly string[],
  onEvent: (event: Record<string, unknown>) => void,
  readyTimeoutMs = 10_000,
): Promise<EmulatorProcess> {
  const child = spawn(path, [...args, '--exit-on-stdin-eof'], { stdio: ['pipe', 'pipe', 'pipe'] });
  let stderr = '';
  child.stderr.on('data', (chunk: Buffer) => (stderr += chunk.toString()));
  const exited = new Promise<{ code: number | null; signal: string | null; stderr: string }>(
    (resolve) => {
      child.once('error', (error) => {
        stderr += error.message;
        resolve({ code: null, signal: null, stderr });
      });
      child.once('exit', (code, signal) => resolve({ code, signal, stderr }));
    },
  );
  let onReady: (line: ReadyLine) => void = () => undefined;
  const readyLine = new Promise<ReadyLine>((resolve) => (onReady = resolve));
  createInterface({ input: child.stdout }).on('line', (line) => {
    let event: unknown;
    try {
      event = JSON.parse(line);
    } catch {
      return; // not an event line
    }
    const ready = ReadyLineSchema.safeParse(event);
    if (ready.success) onReady(ready.data);
    else if (typeof event === 'object' && event !== null) onEvent(event as Record<string, unknown>);
  });
  const stop = async (graceMs = 3000) => {
    if (child.exitCode === null && child.signalCode === null) {
      child.kill('SIGTERM');
      const timer = setTimeout(() => child.kill('SIGKILL'), graceMs);
      await exited;
      clearTimeout(timer);
    }
  };
  const exitedFirst = exited.then((how): never => {
    throw new CliError(
      'FAILED',
      `cube-emulator exited (${how.code ?? how.signal}) before it was ready: ${how.stderr.trim()}`,
    );
  });
  try {
    const ready = await deadline(
      Promise.race([readyLine, exitedFirst]),
      readyTimeoutMs,
      () => new CliError('FAILED', `cube-emulator was not ready within ${readyTimeoutMs} ms`),
    );
    return { ready, exited, stop };
  } catch (error) {
    await stop(500);
    throw error;
  }
}
