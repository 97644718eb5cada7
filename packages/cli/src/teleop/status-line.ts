// A status line that stays the last line of the terminal: redrawn in place, and anything else
// written to stderr meanwhile (a HAL warning) goes on a line of its own above it.
import type { CliIO } from '../io.js';

const CLEAR_LINE = '\r\x1b[K';

export interface StatusLineIO extends CliIO {
  /** Draws `text` as the status line, in place of the one before. */
  showLine(text: string): void;
  /** Ends the status line (a newline after it); later writes go below it. */
  endLine(): void;
}

/** Wraps `io` so that its `err` writes never land on the status line. */
export function withStatusLine(io: CliIO): StatusLineIO {
  let shown: string | undefined;
  return {
    ...io,
    err: (text) => {
      if (shown === undefined) {
        io.err(text);
        return;
      }
      io.err(`${CLEAR_LINE}${text}${text.endsWith('\n') ? '' : '\n'}${shown}`);
    },
    showLine: (text) => {
      shown = text;
      io.err(`${CLEAR_LINE}${text}`);
    },
    endLine: () => {
      if (shown !== undefined) io.err('\n');
      shown = undefined;
    },
  };
}
