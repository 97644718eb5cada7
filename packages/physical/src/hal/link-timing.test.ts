import { robotConfig, V1_ROBOT } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { LinkTiming } from './link-timing.js';

describe('LinkTiming', () => {
  describe('#request', () => {
    it('resends every quarter of the default 2000 ms host timeout and gives up after 3 x 2000 ms', () => {
      const timing = new LinkTiming({}, 1, () => V1_ROBOT);
      expect(timing.request()).toEqual({ timeoutMs: 500, attempts: 12 });
    });

    it('waits at most the protocol 2000 ms per attempt, 3 attempts, with a long host timeout', () => {
      const robot = robotConfig({ hostTimeoutMs: 10_000 });
      expect(new LinkTiming({}, 1, () => robot).request()).toEqual({
        timeoutMs: 2000,
        attempts: 3,
      });
    });

    it('scales the wait by the robot clock rate and keeps the 6000 ms budget', () => {
      const robot = robotConfig({ hostTimeoutMs: 10_000 });
      expect(new LinkTiming({}, 50, () => robot).request()).toEqual({
        timeoutMs: 50,
        attempts: 120,
      });
    });

    it('takes the timeout and attempts given as options', () => {
      const timing = new LinkTiming({ requestTimeoutMs: 20, attempts: 2 }, 1, () => V1_ROBOT);
      expect(timing.request()).toEqual({ timeoutMs: 20, attempts: 2 });
    });
  });

  describe('#heartbeatMs', () => {
    it('beats every quarter of the host timeout, at most every 500 robot ms', () => {
      expect(new LinkTiming({}, 1, () => V1_ROBOT).heartbeatMs()).toBe(500);
      const short = robotConfig({ hostTimeoutMs: 1000 });
      expect(new LinkTiming({}, 1, () => short).heartbeatMs()).toBe(250);
      expect(new LinkTiming({}, 10, () => short).heartbeatMs()).toBe(25);
    });
  });
});
