// A CliIO that records what a command writes, for running `hal` in-process in tests.
import type { CliIO } from '../io.js';

export interface CapturedIO extends CliIO {
  stdout(): string;
  stderr(): string;
  /** Every stdout line parsed as JSON (for --json runs). */
  jsonLines(): unknown[];
  abort(): void;
}

export function captureIO(env: Record<string, string | undefined> = {}): CapturedIO {
  let out = '';
  let err = '';
  const controller = new AbortController();
  return {
    out: (text) => void (out += text),
    err: (text) => void (err += text),
    signal: controller.signal,
    env,
    stdout: () => out,
    stderr: () => err,
    jsonLines: () =>
      out
        .split('\n')
        .filter((line) => line.trim() !== '')
        .map((line) => JSON.parse(line) as unknown),
    abort: () => controller.abort(),
  };
}
