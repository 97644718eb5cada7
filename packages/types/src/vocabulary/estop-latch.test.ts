import { describe, expect, it } from 'vitest';
import { EstopLatch } from './estop-latch.js';

describe('EstopLatch', () => {
  it('starts unlatched, latches with a reason and keeps the latest one', () => {
    const latch = new EstopLatch();
    expect(latch.latched).toBe(false);
    expect(latch.reason).toBeUndefined();
    latch.latch('bumper');
    latch.latch('operator');
    expect(latch.latched).toBe(true);
    expect(latch.reason).toBe('operator');
  });

  it('is cleared by a reset', () => {
    const latch = new EstopLatch();
    latch.latch('operator');
    latch.reset();
    expect(latch.latched).toBe(false);
    expect(latch.reason).toBeUndefined();
  });

  describe('#release', () => {
    it('clears only the e-stop it names: a newer one keeps it latched', () => {
      const latch = new EstopLatch();
      latch.latch('first');
      latch.latch('second');
      expect(latch.release('first')).toBe(false);
      expect(latch.reason).toBe('second');
      expect(latch.release('second')).toBe(true);
      expect(latch.latched).toBe(false);
      expect(latch.release('second')).toBe(false);
    });
  });
});
