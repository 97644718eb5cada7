import { describe, expect, it } from 'vitest';
import { GoalSeekingProvider } from '../decision/deterministic.js';
import { OccupancyGrid } from '../grid/occupancy-grid.js';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';

// Recovery: forgetting weak obstacles, the nudge when there is no route, backing off when stuck.

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('forgets obstacles seen only once when they close every route, and gets through', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 } }));
      const grid = OccupancyGrid.fromMap({ arena: { width: 5, height: 5 } });
      // A stray reading's worth of wall across the whole arena.
      for (let cy = 0; cy < 100; cy += 1) grid.addEvidence(50, cy, 0.85);
      const bridge = new NavigationBridge({
        hal,
        grid,
        provider: new GoalSeekingProvider(),
        rangeSensors: false,
      });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.status).toBe('reached');
      expect(hal.calls.some((c) => c.name === 'moveForward')).toBe(false);
    });

    it('fails with UNREACHABLE, after nudging, when no route reaches the goal', async () => {
      // The goal sits in a closed box of walls.
      const boxes = [
        { minX: 0.8, minY: -0.6, maxX: 1.6, maxY: -0.5 },
        { minX: 0.8, minY: 0.5, maxX: 1.6, maxY: 0.6 },
        { minX: 0.8, minY: -0.6, maxX: 0.9, maxY: 0.6 },
        { minX: 1.5, minY: -0.6, maxX: 1.6, maxY: 0.6 },
      ];
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, boxes }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: {
          arena: { width: 5, height: 5 },
          obstacles: boxes.map((b) => ({
            kind: 'box' as const,
            x: (b.minX + b.maxX) / 2,
            y: (b.minY + b.maxY) / 2,
            width: b.maxX - b.minX,
            depth: b.maxY - b.minY,
          })),
        },
      });
      const outcome = await bridge.run({ x: 1.2, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('UNREACHABLE');
      expect(hal.calls.some((c) => c.name === 'moveForward' && c.args[0] === 10)).toBe(true);
      expect(hal.collisions).toBe(0);
    });

    it('fails with STUCK when motions succeed but the robot does not move', async () => {
      const hal = await ready(new FakeHAL());
      hal.fault = () => 'freeze';
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxStuckRecoveries: 2,
      });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('STUCK');
      // Recovery backed off and turned before giving up.
      expect(hal.calls.some((c) => c.name === 'moveBackward')).toBe(true);
      expect(hal.calls.some((c) => c.name === 'rotate')).toBe(true);
    });
  });
});
