import { describe, expect, it } from 'vitest';
import { defaultThreads } from './threads.js';

describe('defaultThreads', () => {
  it('leaves one core to the robot, uses at least one and at most four', () => {
    expect([1, 2, 3, 4, 8, 64].map((cores) => defaultThreads(cores))).toEqual([1, 1, 2, 3, 4, 4]);
  });
});
