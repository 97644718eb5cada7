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

  it('holds the work from callBegan to callEnded, and never counts a call below none', async () => {
    const { background, add, done } = work();
    background.callBegan();
    background.callBegan();
    add(1, 2);
    await sleep(30);
    background.callEnded(0.05);
    // one of the two calls still on its way
    await sleep(30);
    expect(done).toEqual([]);
    background.callEnded(0.05);
    await expect.poll(() => done, { timeout: 2000, interval: 5 }).toEqual([1, 2]);
    // an answer too many is ignored: the next call still holds the work back
    background.callEnded(0.05);
    background.callBegan();
    add(3);
    await sleep(30);
    expect(done).toEqual([1, 2]);
    background.callEnded(0.05);
    await expect.poll(() => done, { timeout: 2000, interval: 5 }).toEqual([1, 2, 3]);
    background.stop();
  });

  it('keeps its window when a call is ended with a duration that is not one', () => {
    const { background } = work({ sliceMs: 1 });
    background.callBegan();
    background.callEnded(0.4);
    expect(background.windowMs()).toBeCloseTo(0.1, 6);
    for (const bad of [Number.NaN, -1, Number.POSITIVE_INFINITY]) {
      background.callBegan();
      background.callEnded(bad);
    }
    expect(background.windowMs()).toBeCloseTo(0.1, 6);
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

describe('BackgroundWork while calls come back to back', () => {
  it('takes a quarter of a typical call for a window, and one slow call moves it little', () => {
    let clock = 0;
    const background = new BackgroundWork({
      step: () => false,
      hasWork: () => false,
      maxHoldMs: 0,
      sliceMs: 1,
      tickMs: 5,
      now: () => clock,
    });
    const callOf = (ms: number): void => {
      const answered = background.callStarted();
      clock += ms;
      answered();
    };
    // no call yet: a slice
    expect(background.windowMs()).toBe(1);
    callOf(2);
    expect(background.windowMs()).toBe(0.5);
    // a stall: the average moves by 1/16 of twice the typical call, not of the stall
    callOf(100);
    expect(background.windowMs()).toBeCloseTo((2 + (4 - 2) / 16) / 4, 10);
    // short calls take it down, to 0.02 ms at least; long ones up, to the slice at most
    for (let i = 0; i < 200; i++) callOf(0.001);
    expect(background.windowMs()).toBe(0.02);
    for (let i = 0; i < 200; i++) callOf(50);
    expect(background.windowMs()).toBe(1);
  });

  it('gives each call one window of work in the next turn once work has waited maxHoldMs', async () => {
    // each call is timed as 2 ms however loaded the machine is, so the window (a quarter of a
    // typical call) stays 0.5 ms throughout
    let clock = 0;
    const { background, add, done } = work({ maxHoldMs: 0, sliceMs: 1, pieceMs: 0.1 });
    const callStarted = (): (() => void) => {
      const at = (clock += 2);
      const answered = background.callStarted(at);
      return () => answered(at + 2);
    };
    for (let i = 0; i < 4; i++) callStarted()();
    expect(background.windowMs()).toBe(0.5);
    const perWindow = Math.ceil(0.5 / 0.1) + 1;
    let onItsWay = callStarted();
    add(...Array.from({ length: 200 }, (_, i) => i));
    // the first tick finds work held past the hold, a call on its way: one window
    await expect.poll(() => done.length, { timeout: 2000, interval: 1 }).toBeGreaterThan(0);
    for (let call = 0; call < 5; call++) {
      const before = done.length;
      // the next call starts before this one answers: a call is on its way all along
      const next = callStarted();
      onItsWay();
      onItsWay = next;
      expect(done.length).toBe(before);
      await new Promise<void>((resolve) => nextTurn(resolve));
      await new Promise<void>((resolve) => nextTurn(resolve));
      const ran = done.length - before;
      expect(ran).toBeGreaterThanOrEqual(1);
      // the call's window, and on a loaded machine a tick's window in each of the two turns
      expect(ran).toBeLessThanOrEqual(3 * perWindow);
    }
    expect(background.windowMs()).toBe(0.5);
    expect(done.length).toBeLessThan(200);
    onItsWay();
    // once no call is on its way, a tick runs the rest in slices
    await expect.poll(() => done.length, { timeout: 2000, interval: 5 }).toBe(200);
    background.stop();
  });
});
