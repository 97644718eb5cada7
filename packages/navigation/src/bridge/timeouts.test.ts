import { afterEach, describe, expect, it, vi } from 'vitest';
import { GoalSeekingProvider } from '../decision/deterministic.js';
import type { DecisionProvider } from '../decision/provider.js';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';

// Nothing waits forever: motions, the pose, the sensors and the camera are bounded.

afterEach(() => {
  vi.useRealTimers();
});

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('fails with TIMEOUT, and stops the wheels, when a motion never finishes', async () => {
      vi.useFakeTimers();
      const hal = await ready(new FakeHAL());
      hal.fault = (call) => (call.name === 'moveTo' ? 'hang' : undefined);
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const running = bridge.run({ x: 1, y: 0 });
      await vi.advanceTimersByTimeAsync(120_000);
      const outcome = await running;
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('TIMEOUT');
      expect(outcome.message).toContain("bridge's limit");
      expect(hal.calls.at(-1)?.name).toBe('stop');
    });

    it('fails with TIMEOUT when getPose never answers', async () => {
      vi.useFakeTimers();
      const hal = await ready(new FakeHAL());
      hal.locomotion.getPose = () => new Promise(() => undefined);
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const running = bridge.run({ x: 1, y: 0 });
      await vi.advanceTimersByTimeAsync(30_000);
      const outcome = await running;
      expect(outcome.reason).toBe('TIMEOUT');
      expect(outcome.message).toContain('getPose');
    });

    it('goes on without readings or frames when the sensors and the camera never answer', async () => {
      vi.useFakeTimers();
      const hal = await ready(new FakeHAL());
      hal.vision.getDistanceSensors = () => new Promise(() => undefined);
      hal.vision.captureFrame = () => new Promise(() => undefined);
      const frames: (string | undefined)[] = [];
      const seeking = new GoalSeekingProvider();
      const provider: DecisionProvider = {
        name: 'camera-user',
        wantsFrame: true,
        decide: (context) => {
          frames.push(context.frame);
          return seeking.decide(context);
        },
      };
      const bridge = new NavigationBridge({ hal, provider });
      const running = bridge.run({ x: 1, y: 0 });
      await vi.advanceTimersByTimeAsync(120_000);
      const outcome = await running;
      expect(outcome.status).toBe('reached');
      expect(frames.length).toBeGreaterThan(0);
      expect(frames.every((f) => f === undefined)).toBe(true);
    });
  });
});
