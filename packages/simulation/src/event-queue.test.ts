import { describe, expect, it } from 'vitest';
import { EventQueue } from './event-queue.js';

describe('EventQueue', () => {
  it('gives the earliest item first, ties in order of arrival, after moves and removals', () => {
    const queue = new EventQueue<string>();
    for (const [item, time] of [
      ['a', 50],
      ['b', 10],
      ['c', 30],
      ['d', 10],
      ['e', 70],
    ] as const) {
      queue.set(item, time);
    }
    queue.set('e', 5); // moved earlier
    queue.set('b', 60); // moved later
    queue.delete('c');
    queue.delete('zz'); // not queued: nothing happens
    const order: string[] = [];
    while (queue.size > 0) {
      const item = queue.peek() as string;
      order.push(`${item}@${queue.peekTime()}`);
      queue.delete(item);
    }
    expect(order).toEqual(['e@5', 'd@10', 'a@50', 'b@60']);
    expect(queue.peekTime()).toBe(Number.POSITIVE_INFINITY);
  });

  it('keeps a thousand random updates in order', () => {
    const queue = new EventQueue<number>();
    const times = new Map<number, number>();
    let seed = 7;
    const next = () => (seed = (seed * 48271) % 2147483647) / 2147483647;
    for (let i = 0; i < 1000; i += 1) {
      const item = Math.floor(next() * 100);
      const time = Math.floor(next() * 1000);
      queue.set(item, time);
      times.set(item, time);
    }
    let last = -1;
    while (queue.size > 0) {
      const item = queue.peek() as number;
      expect(queue.peekTime()).toBe(times.get(item));
      expect(queue.peekTime()).toBeGreaterThanOrEqual(last);
      last = queue.peekTime();
      queue.delete(item);
    }
  });
});
