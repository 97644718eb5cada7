// Raw mode on the terminal for the length of a function, restored on every way out (return,
// throw, abort), so a crashed or interrupted teleop never leaves the user's shell unusable.
import { CliError } from '../cli-error.js';
import type { CliIO } from '../io.js';

export type TerminalInput = NonNullable<CliIO['stdin']>;

/** The terminal, or a USAGE error saying why there is none. */
export function requireTerminal(io: CliIO): TerminalInput & { setRawMode(raw: boolean): unknown } {
  const stdin = io.stdin;
  if (stdin === undefined || stdin.isTTY !== true || typeof stdin.setRawMode !== 'function') {
    throw new CliError(
      'USAGE',
      'hal teleop reads the keyboard: run it in a terminal (its standard input is not a TTY)',
    );
  }
  return stdin as TerminalInput & { setRawMode(raw: boolean): unknown };
}

/** Runs `use` with `stdin` in raw mode, reading; restores cooked mode and pauses it after. */
export async function withRawMode<T>(
  stdin: TerminalInput & { setRawMode(raw: boolean): unknown },
  use: () => Promise<T>,
): Promise<T> {
  stdin.setRawMode(true);
  stdin.resume();
  try {
    return await use();
  } finally {
    stdin.setRawMode(false);
    stdin.pause();
  }
}
