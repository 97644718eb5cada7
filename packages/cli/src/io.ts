// Where a command writes, and how: human text, or one JSON document per result with --json.
// Commands never touch process.stdout directly, so tests run them in-process and read the output.

/** The streams and signals a command runs with. */
export interface CliIO {
  /** Standard output: results. */
  out(text: string): void;
  /** Standard error: progress, warnings and errors. */
  err(text: string): void;
  /** Aborted on SIGINT/SIGTERM (or by a test): long-running commands stop cleanly. */
  signal: AbortSignal;
  /** Keyboard input for interactive commands (`teleop`); absent when stdin is not a terminal. */
  stdin?: NodeJS.ReadableStream & { setRawMode?: (raw: boolean) => unknown; isTTY?: boolean };
  /** The environment (defaults for options such as `$NATS_URL`). */
  env: Readonly<Record<string, string | undefined>>;
}

/** Options every command shares (declared on the root program). */
export interface GlobalOptions {
  /** Machine-readable output: one JSON document per line on stdout, errors as JSON on stderr. */
  json: boolean;
}

/** Writes one result: `value` as a JSON line with --json, else the human text. */
export function emit(io: CliIO, global: GlobalOptions, value: unknown, human: () => string): void {
  if (global.json) io.out(`${JSON.stringify(value)}\n`);
  else {
    const text = human();
    io.out(text.endsWith('\n') ? text : `${text}\n`);
  }
}

/** Writes progress for people (suppressed with --json, so stdout stays parseable). */
export function progress(io: CliIO, global: GlobalOptions, text: string): void {
  if (!global.json) io.err(text.endsWith('\n') ? text : `${text}\n`);
}
