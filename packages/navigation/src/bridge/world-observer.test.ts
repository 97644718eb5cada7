import { describe, expect, it } from 'vitest';
import type { Logger } from '@hal/types';
import { GoalSeekingProvider } from '../decision/deterministic.js';
import { FakeHAL, ready, wall } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import { decision, ScriptedProvider } from './scripted-provider.fixture.js';
import type { WorldObservation, WorldObserver } from './world-observer.js';

// The bridge's seam for perception: an observer told each cycle's frame and pose, that maps what
// it sees into the grid. Here a fake camera: rays across 60 degrees ahead against the fake world.

/** A camera-like observer: free space up to the first box along each ray, occupied there. */
function fakeCamera(hal: FakeHAL, seen: WorldObservation[] = []): WorldObserver {
  return (observation) => {
    seen.push(observation);
    const { pose, grid } = observation;
    for (let deg = -30; deg <= 30; deg += 1) {
      const angle = pose.yaw + (deg * Math.PI) / 180;
      const range = hal.range(angle) + hal.radius;
      const hit = range < 1.5;
      grid.integrateRay(pose.x, pose.y, angle, Math.min(range, 1.5), hit);
    }
  };
}

/** A logger that keeps the warnings. */
function warnings(): { logger: Logger; warned: string[] } {
  const warned: string[] = [];
  const logger: Logger = {
    log: (level, _namespace, message) => {
      if (level === 'warn') warned.push(message);
    },
  };
  return { logger, warned };
}

describe('NavigationBridge', () => {
  describe('observe', () => {
    it('maps what the observer sees: a robot with no range sensors and no map drives round a wall', async () => {
      const start = { x: -1.5, y: 0.4, yaw: 0 };
      const goal = { x: 1.5, y: 0.4 };
      const blind = await ready(new FakeHAL({ start, boxes: [wall], rangeSensors: false }));
      const without = await new NavigationBridge({
        hal: blind,
        provider: new GoalSeekingProvider(),
      }).run(goal);
      expect(without.reason).toBe('COLLISION');

      const hal = await ready(new FakeHAL({ start, boxes: [wall], rangeSensors: false }));
      const seen: WorldObservation[] = [];
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        observe: fakeCamera(hal, seen),
      });
      const outcome = await bridge.run(goal);
      expect(outcome.status, outcome.message).toBe('reached');
      expect(hal.collisions).toBe(0);
      // It went round the top of the wall, which it had mapped on the way.
      expect(Math.max(...outcome.trajectory.map((p) => p.y))).toBeGreaterThan(1.2);
      expect(bridge.grid.isTraversable(0, 0)).toBe(false);
      // Once per cycle, with the cycle's frame and the pose that cycle read.
      expect(seen.map((o) => o.cycle)).toEqual(
        Array.from({ length: outcome.cycles }, (_, k) => k + 1),
      );
      expect(seen.every((o) => o.frame === 'data:image/jpeg;base64,AAAA')).toBe(true);
      expect(seen[0]?.pose).toEqual(start);
      expect(seen.map((o) => o.pose)).toEqual(outcome.trajectory.slice(0, seen.length));
    });

    it('observes before the provider decides, and gives no frame to a provider that wants none', async () => {
      const hal = await ready(new FakeHAL({ rangeSensors: false }));
      const provider = new ScriptedProvider([decision({ type: 'STOP' }, true)]);
      let occupiedWhenDeciding = false;
      const bridge = new NavigationBridge({
        hal,
        provider,
        observe: ({ grid }) => grid.integrateRay(0, 0, 0, 1, true),
      });
      bridge.on('decision', () => {
        occupiedWhenDeciding = bridge.grid.stateAt(1, 0) === 'occupied';
      });
      await bridge.run(null);
      expect(occupiedWhenDeciding).toBe(true);
      expect(provider.contexts[0]?.frame).toBeUndefined();
    });

    it('goes on without an observer that fails or never finishes, and says so', async () => {
      for (const observe of [
        () => Promise.reject(new Error('decoder broke')),
        () => new Promise<void>(() => undefined),
      ]) {
        const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 } }));
        const { logger, warned } = warnings();
        const bridge = new NavigationBridge({
          hal,
          provider: new GoalSeekingProvider(),
          observe,
          sensorTimeoutMs: 50,
          logger,
        });
        const outcome = await bridge.run({ x: 0, y: 0 });
        expect(outcome.status, outcome.message).toBe('reached');
        expect(warned.some((w) => w.includes('world observer'))).toBe(true);
      }
    });

    it('refuses an observe option that is not a function', () => {
      const hal = new FakeHAL();
      const observe = 'camera' as unknown as WorldObserver;
      expect(
        () => new NavigationBridge({ hal, provider: new GoalSeekingProvider(), observe }),
      ).toThrow(/"observe" must be a function/);
    });
  });
});
