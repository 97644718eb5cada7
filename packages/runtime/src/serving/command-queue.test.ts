import { describe, expect, it } from 'vitest';
import { CommandQueue } from './command-queue.js';

const later = (ms: number, value: string, log: string[]) => () =>
  new Promise<string>((resolve) =>
    setTimeout(() => {
      log.push(value);
      resolve(value);
    }, ms),
  );

describe('CommandQueue', () => {
  it('runs queued tasks one at a time, in order, even when one fails', async () => {
    const queue = new CommandQueue();
    const log: string[] = [];
    const a = queue.run(later(30, 'a', log));
    const b = queue.run(() => Promise.reject(new Error('b failed')));
    const c = queue.run(later(1, 'c', log));
    expect(queue.pending).toBe(3);
    await expect(b).rejects.toThrow('b failed');
    expect(await Promise.all([a, c])).toEqual(['a', 'c']);
    expect(log).toEqual(['a', 'c']);
    expect(queue.pending).toBe(0);
  });

  it('starts a priority task at once, ahead of everything queued', async () => {
    const queue = new CommandQueue();
    const log: string[] = [];
    const slow = queue.run(later(40, 'slow', log));
    const queued = queue.run(later(1, 'queued', log));
    await queue.run(later(1, 'priority', log), true);
    await Promise.all([slow, queued]);
    expect(log).toEqual(['priority', 'slow', 'queued']);
  });
});
