// A child process that reports what happens as one JSON object per line on its standard output
// (the emulator, the host processes of the fault tests): the events so far, and a bounded wait
// for one that matches.
import type { ChildProcessByStdio } from 'node:child_process';
import { createInterface } from 'node:readline';
import type { Readable, Writable } from 'node:stream';

type EventChild = ChildProcessByStdio<Writable | null, Readable, Readable>;

export interface EventLines<E> {
  /** Every event printed so far (a line that is not JSON is `{ event: 'unparsed', line }`). */
  events: E[];
  /** Waits for an event that matches, up to `timeoutMs`; rejects early when the child exits. */
  waitFor(match: (e: E) => boolean, timeoutMs?: number): Promise<E>;
  /**
   * Waits until `count` events match, up to `timeoutMs`, and returns every one that matches.
   * A child's stdout can arrive after the reply its event belongs to, so a test that counts the
   * events of calls it has just made waits for them with this.
   */
  waitForCount(match: (e: E) => boolean, count: number, timeoutMs?: number): Promise<E[]>;
}

/** Reads `child`'s events; `name` and `defaultTimeoutMs` shape its errors and waits. */
export function readEventLines<E extends { event: string }>(
  child: EventChild,
  name: string,
  defaultTimeoutMs: number,
): EventLines<E> {
  const events: E[] = [];
  const waiters = new Set<() => void>();
  let stderr = '';
  child.stderr.on('data', (chunk: Buffer) => {
    stderr += chunk.toString();
  });
  createInterface({ input: child.stdout }).on('line', (line) => {
    try {
      events.push(JSON.parse(line) as E);
    } catch {
      events.push({ event: 'unparsed', line } as unknown as E);
    }
    for (const wake of waiters) wake();
  });
  child.once('exit', () => {
    for (const wake of waiters) wake();
  });

  const waitFor = (match: (e: E) => boolean, timeoutMs = defaultTimeoutMs) =>
    new Promise<E>((resolve, reject) => {
      const check = () => {
        const found = events.find(match);
        if (found !== undefined) {
          done();
          resolve(found);
        } else if (child.exitCode !== null || child.signalCode !== null) {
          done();
          reject(new Error(`${name} exited (${child.exitCode ?? child.signalCode}): ${stderr}`));
        }
      };
      const timer = setTimeout(() => {
        done();
        reject(new Error(`${name}: no matching event within ${timeoutMs} ms: ${stderr}`));
      }, timeoutMs);
      const done = () => {
        clearTimeout(timer);
        waiters.delete(check);
      };
      waiters.add(check);
      check();
    });
  const waitForCount = async (match: (e: E) => boolean, count: number, timeoutMs?: number) => {
    try {
      await waitFor(() => events.filter(match).length >= count, timeoutMs);
    } catch (error) {
      const seen = events.filter(match).length;
      throw new Error(`${(error as Error).message} (${seen} of ${count} matching events)`);
    }
    return events.filter(match);
  };
  return { events, waitFor, waitForCount };
}
