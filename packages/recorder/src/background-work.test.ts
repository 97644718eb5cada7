import { describe, expect, it } from 'vitest';
import { nextTurn } from '@hal/types';
import { BackgroundWork } from './background-work.js';

const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/** A BackgroundWork over a list of pieces of work; `done` lists the pieces run, in order. */
function work(options: { maxHoldMs?: number; sliceMs?: number; pieceMs?: number } = {}) {
  const pending: number[] = [];
  const done: number[] = [];
  const background = new BackgroundWork({
    step: () => {
      const piece = pending.shift();
      if (piece === undefined) return false;
      // a piece that takes CPU time, as encoding and compressing do
      const until = performance.now() + (options.pieceMs ?? 0);
      while (performance.now() < until);
      if (piece < 0) throw new Error(`piece ${piece} fails`);
      done.push(piece);
      return true;
    },
    hasWork: () => pending.length > 0,
    maxHoldMs: options.maxHoldMs ?? 10_000,
    sliceMs: options.sliceMs ?? 1,
    tickMs: 5,
  });
  const add = (...pieces: number[]): void => {
    pending.push(...pieces);
    background.kick();
  };
  return { background, add, done, pending };
}

describe('BackgroundWork', () => {
  it('waits while a call is on its way, and runs once it has answered', async () => {
    const { background, add, done } = work();
    const answered = background.callStarted();
    add(1, 2, 3);
    // ten ticks with the call on its way: nothing runs
    await sleep(50);
    expect(done).toEqual([]);
    answered();
    await expect.poll(() => done, { timeout: 2000, interval: 5 }).toEqual([1, 2, 3]);
    background.stop();
  });

  it('stops between two slices when a call starts, and goes on once it has answered', async () => {
    const { background, add, done } = work({ sliceMs: 1, pieceMs: 0.4 });
    add(...Array.from({ length: 20 }, (_, i) => i));
    // the first slice runs at the next tick; a call starts in a turn after it
    await expect.poll(() => done.length, { timeout: 2000, interval: 1 }).toBeGreaterThan(0);
    const answered = background.callStarted();
    const atStart = done.length;
    await sleep(40);
    expect(atStart).toBeLessThan(20);
    // at most the slice that was running when the call started finished
    expect(done.length).toBeLessThanOrEqual(atStart + 3);
    answered();
    await expect.poll(() => done.length, { timeout: 2000, interval: 5 }).toBe(20);
    background.stop();
  });

  it('runs between calls once work has waited maxHoldMs, calls still on their way', async () => {
    const { background, add, done } = work({ maxHoldMs: 40 });
    const answered = background.callStarted();
    const queuedAt = performance.now();
    add(1);
    await expect.poll(() => done, { timeout: 2000, interval: 5 }).toEqual([1]);
    expect(performance.now() - queuedAt).toBeGreaterThanOrEqual(40);
    // still catching up: the next work runs in a later turn, without waiting for the hold again
    add(2);
    await sleep(20);
    expect(done).toEqual([1, 2]);
    answered();
    background.stop();
  });

  it('holds work again after a pause: the hold counts from the work held back, not an earlier burst', async () => {
    const { background, add, done } = work({ maxHoldMs: 100 });
    const first = background.callStarted();
    add(1);
    await sleep(30);
    first();
    // the work runs before a tick has seen the call answered
    await background.flush();
    expect(done).toEqual([1]);
    // a pause longer than the hold, then a new burst: its work waits again
    await sleep(120);
    const second = background.callStarted();
    add(2);
    await sleep(40);
    expect(done).toEqual([1]);
    second();
    await expect.poll(() => done, { timeout: 2000, interval: 5 }).toEqual([1, 2]);
    background.stop();
  });

  it('counts each call once, however often its end is marked', async () => {
    const { background, add, done } = work();
    const first = background.callStarted();
    const second = background.callStarted();
    first();
    first();
    add(1);
    await sleep(40);
    // the second call is still on its way
    expect(done).toEqual([]);
    second();
    await expect.poll(() => done, { timeout: 2000, interval: 5 }).toEqual([1]);
    background.stop();
  });

  it('flush runs every piece, a call on its way or not, and resolves when none is left', async () => {
    const { background, add, done } = work();
    background.callStarted();
    add(1, 2, 3);
    await background.flush();
    expect(done).toEqual([1, 2, 3]);
    background.stop();
  });

  it('yields to the event loop after each slice, so a reply or a call can go first', async () => {
    const { background, add, done } = work({ sliceMs: 1, pieceMs: 0.4 });
    add(...Array.from({ length: 20 }, (_, i) => i));
    // count the turns of the event loop that pass while the work runs
    let turns = 0;
    let counting = true;
    const count = (): void => {
      turns += 1;
      if (counting) nextTurn(count);
    };
    nextTurn(count);
    await background.flush();
    counting = false;
    expect(done).toHaveLength(20);
    // 8 ms of work in slices of at most 1 ms (about 3 pieces each): several turns in between
    expect(turns).toBeGreaterThanOrEqual(4);
    background.stop();
  });

  it('goes on past a piece that throws', async () => {
    const { background, add, done } = work();
    add(1, -1, 2);
    await background.flush();
    expect(done).toEqual([1, 2]);
    background.stop();
  });
});
