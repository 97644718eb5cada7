// Questions to the person at the terminal, each bounded by a timeout (and by Ctrl-C): a
// calibration that nobody answers ends with an error instead of holding the robot's link forever.
import { createInterface } from 'node:readline/promises';
import { CliError } from '../cli-error.js';
import type { CliIO } from '../io.js';

/** Asks questions on `io.stdin`, writing each question to stderr. */
export interface Prompter {
  /** The answer line, trimmed; TIMEOUT-like FAILED after `timeoutMs`, FAILED on Ctrl-C. */
  line(question: string): Promise<string>;
  /** A number > 0 (asked again, at most three times, until one is typed). */
  positive(question: string, unit: string): Promise<number>;
  close(): void;
}

/** Whether `io` has a terminal to ask on. */
export function canPrompt(io: CliIO): boolean {
  return io.stdin?.isTTY === true;
}

export function prompter(io: CliIO, timeoutMs: number): Prompter {
  const input = io.stdin;
  if (input === undefined) throw new CliError('USAGE', 'no terminal to ask on');
  const rl = createInterface({ input, terminal: false });
  const line = async (question: string): Promise<string> => {
    io.err(question);
    const signal = AbortSignal.any([io.signal, AbortSignal.timeout(timeoutMs)]);
    try {
      return (await rl.question('', { signal })).trim();
    } catch (error) {
      if (io.signal.aborted) throw new CliError('FAILED', 'calibration interrupted', 130);
      if (signal.aborted) {
        throw new CliError('FAILED', `no answer within ${Math.round(timeoutMs / 1000)} s`);
      }
      throw error;
    }
  };
  return {
    line,
    positive: async (question, unit) => {
      for (let attempt = 1; ; attempt += 1) {
        const answer = await line(question);
        const value = Number(answer);
        if (answer !== '' && Number.isFinite(value) && value > 0) return value;
        if (attempt === 3) {
          throw new CliError('USAGE', `expected a number > 0 ${unit}, got "${answer}"`);
        }
        io.err(`  a number > 0 ${unit}, please (for example 98.5)\n`);
      }
    },
    close: () => rl.close(),
  };
}
