import { describe, expect, it } from 'vitest';
import { Fifo } from './fifo.js';

describe('Fifo', () => {
  it('hands items back in order, through compactions, interleaved with pushes', () => {
    const fifo = new Fifo<number>();
    const taken: number[] = [];
    let next = 0;
    // grows to thousands, then drains and refills, as a recording behind a loop does
    for (let round = 0; round < 5; round++) {
      for (let i = 0; i < 3000; i++) fifo.push(next++);
      for (let i = 0; i < 2500; i++) taken.push(fifo.shift()!);
      expect(fifo.length).toBe(next - taken.length);
    }
    while (fifo.length > 0) taken.push(fifo.shift()!);
    expect(taken).toEqual(Array.from({ length: next }, (_, i) => i));
    expect(fifo.shift()).toBeUndefined();
    expect(fifo.length).toBe(0);
    fifo.push(7);
    expect(fifo.shift()).toBe(7);
  });
});
