// Waits, bounded, for a command running in-process to write something (tests of long-running
// commands: `serve`, `status --watch`, `teleop`).
import type { CapturedIO } from './testing/capture-io.js';

/** Resolves once `match(io)` is true; rejects with what was written after `timeoutMs`. */
export async function waitForOutput(
  io: CapturedIO,
  match: (io: CapturedIO) => boolean,
  timeoutMs = 20_000,
): Promise<void> {
  const deadline = Date.now() + timeoutMs;
  while (!match(io)) {
    if (Date.now() > deadline) {
      throw new Error(`no such output in ${timeoutMs} ms:\n${io.stdout()}\n${io.stderr()}`);
    }
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
}
