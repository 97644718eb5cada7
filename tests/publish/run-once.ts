// Work done once per test run for several test files, which vitest runs in separate processes:
// the first file to ask does it, the others wait for its result. A folder the run's global setup
// made (published.global.ts) holds the results; `mkdir` of a lock folder decides who does it, and
// the result file appears whole (written aside, then renamed), so a waiting file never reads half.
import { mkdirSync, readFileSync, renameSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { setTimeout as delay } from 'node:timers/promises';

/** What a file that did the work left for the others: its result, or why it failed. */
type Outcome<T> = { ok: true; value: T } | { ok: false; message: string };

function readOutcome<T>(file: string): Outcome<T> | undefined {
  try {
    return JSON.parse(readFileSync(file, 'utf8')) as Outcome<T>;
  } catch (error) {
    if ((error as NodeJS.ErrnoException).code === 'ENOENT') return undefined;
    throw error;
  }
}

/**
 * Runs `work` once for `name` in `dir` across the run's test files and resolves every caller with
 * its result (which must survive JSON). A failure reaches every caller, with the message of the
 * one that ran it.
 */
export async function runOnce<T>(dir: string, name: string, work: () => Promise<T>): Promise<T> {
  const file = join(dir, `${name}.json`);
  let mine = true;
  try {
    mkdirSync(join(dir, `${name}.lock`));
  } catch (error) {
    if ((error as NodeJS.ErrnoException).code !== 'EEXIST') throw error;
    mine = false;
  }
  if (mine) {
    let outcome: Outcome<T>;
    try {
      outcome = { ok: true, value: await work() };
    } catch (error) {
      outcome = { ok: false, message: error instanceof Error ? error.message : String(error) };
    }
    writeFileSync(`${file}.partial`, JSON.stringify(outcome));
    renameSync(`${file}.partial`, file);
  }
  // the hook's own timeout ends a wait for a file that never comes
  let outcome = readOutcome<T>(file);
  while (outcome === undefined) {
    await delay(200);
    outcome = readOutcome<T>(file);
  }
  if (!outcome.ok) throw new Error(`${name}, done once for the run, failed: ${outcome.message}`);
  return outcome.value;
}
