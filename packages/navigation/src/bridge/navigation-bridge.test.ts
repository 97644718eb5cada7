import { describe, expect, it } from 'vitest';
import { FrontierExplorationProvider, GoalSeekingProvider } from '../decision/deterministic.js';
import { OccupancyGrid } from '../grid/occupancy-grid.js';
import { FakeHAL, ready, wall, wallMap } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import type { NavigationEvents } from './navigation-events.js';

// The loop end to end on the fake robot: routes, legs, mapping, exploring, and the run lifecycle.

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('reaches a goal behind a wall with the goal-seeking provider, without touching it', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1.5, y: -1, yaw: 0 }, boxes: [wall] }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: wallMap,
      });
      const events: string[] = [];
      for (const name of ['cycle', 'decision', 'path', 'result', 'done'] as const) {
        bridge.on(name, () => events.push(name));
      }
      const outcome = await bridge.run({ x: 1.5, y: -1 });
      expect(outcome.status).toBe('reached');
      expect(outcome.reason).toBe('GOAL_REACHED');
      expect(hal.collisions).toBe(0);
      expect(outcome.distanceToGoalM).toBeLessThanOrEqual(0.1);
      expect(Math.hypot(hal.x - 1.5, hal.y + 1)).toBeLessThanOrEqual(0.1);
      // It went round the top of the wall.
      expect(Math.max(...outcome.trajectory.map((p) => p.y))).toBeGreaterThan(1.2);
      expect(events.slice(0, 4)).toEqual(['cycle', 'decision', 'path', 'result']);
      expect(events.at(-1)).toBe('done');
      expect(outcome.trajectory[0]).toEqual({ x: -1.5, y: -1, yaw: 0 });
      expect(outcome.cycles).toBe(outcome.trajectory.length - 1);
    });

    it('drives legs no longer than maxLegM, each to a point the robot may stand on', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1.5, y: -1, yaw: 0 }, boxes: [wall] }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: wallMap,
        maxLegM: 0.4,
      });
      const legs: NavigationEvents['path'][] = [];
      bridge.on('path', (e) => legs.push(e));
      const outcome = await bridge.run({ x: 1.5, y: -1 });
      expect(outcome.status).toBe('reached');
      let from = outcome.trajectory[0] as { x: number; y: number };
      for (const [k, e] of legs.entries()) {
        expect(Math.hypot(e.leg.x - from.x, e.leg.y - from.y)).toBeLessThanOrEqual(0.4 + 1e-9);
        expect(bridge.grid.isTraversable(e.leg.x, e.leg.y)).toBe(true);
        from = outcome.trajectory[k + 1] as { x: number; y: number };
      }
    });

    it('maps an obstacle missing from its map with the range sensors and drives round it', async () => {
      const box = { minX: 0.4, minY: -0.5, maxX: 0.8, maxY: 0.5 };
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, boxes: [box] }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: { arena: { width: 5, height: 5 } },
        maxLegM: 0.3,
      });
      const outcome = await bridge.run({ x: 1.5, y: 0 });
      expect(outcome.status).toBe('reached');
      expect(hal.collisions).toBe(0);
      expect(bridge.grid.stateAt(0.42, 0)).toBe('occupied');
    });

    it('takes short legs into unknown space when it has range sensors, long ones through known space', async () => {
      const legs: number[] = [];
      const run = async (grid: OccupancyGrid) => {
        // Short-sighted sensors: what lies ahead stays unknown until the robot is nearly there.
        const hal = await ready(new FakeHAL({ start: { x: -1.5, y: 0, yaw: 0 }, maxRange: 0.1 }));
        const bridge = new NavigationBridge({
          hal,
          grid,
          provider: new GoalSeekingProvider(),
          rangeSensors: { maxRangeM: 0.1 },
        });
        legs.length = 0;
        let from = { x: -1.5, y: 0 };
        bridge.on('path', (e) => legs.push(Math.hypot(e.leg.x - from.x, e.leg.y - from.y)));
        bridge.on('cycle', (e) => {
          from = e.pose;
        });
        return bridge.run({ x: 1.5, y: 0 });
      };
      const unknown = new OccupancyGrid();
      unknown.seedFromMap({ arena: { width: 5, height: 5 } }, { freeSpace: false });
      expect((await run(unknown)).status).toBe('reached');
      expect(Math.max(...legs)).toBeLessThanOrEqual(0.15 + 1e-9);
      const known = OccupancyGrid.fromMap({ arena: { width: 5, height: 5 } });
      expect((await run(known)).status).toBe('reached');
      expect(Math.max(...legs)).toBeCloseTo(0.5, 9);
    });

    it('works without range sensors, from the known map alone', async () => {
      const hal = await ready(
        new FakeHAL({ start: { x: -1.5, y: -1, yaw: 0 }, boxes: [wall], rangeSensors: false }),
      );
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        map: wallMap,
      });
      const outcome = await bridge.run({ x: 1.5, y: -1 });
      expect(outcome.status).toBe('reached');
      expect(hal.collisions).toBe(0);
    });

    it('explores a walled room until no frontier is left', async () => {
      const hal = await ready(new FakeHAL({ arena: 1.6, start: { x: 0, y: 0, yaw: 0 } }));
      const grid = new OccupancyGrid({ widthM: 2, heightM: 2 });
      const bridge = new NavigationBridge({
        hal,
        grid,
        provider: new FrontierExplorationProvider(),
        maxCycles: 150,
      });
      const outcome = await bridge.run(null);
      expect(outcome.status).toBe('reached');
      expect(outcome.reason).toBe('EXPLORATION_COMPLETE');
      expect(hal.collisions).toBe(0);
      // The inside of the room is known.
      expect(grid.stateAt(0.5, 0.5)).toBe('free');
      expect(grid.stateAt(-0.5, -0.5)).toBe('free');
    });

    it('is stopped by stop() during a run, and by an aborted signal', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -2, y: 0, yaw: 0 } }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.2,
      });
      bridge.on('result', () => void bridge.stop());
      const outcome = await bridge.run({ x: 2, y: 0 });
      expect(outcome.status).toBe('stopped');
      expect(outcome.reason).toBe('STOP_REQUESTED');
      expect(outcome.cycles).toBe(1);
      expect(bridge.running).toBe(false);

      const aborted = new AbortController();
      aborted.abort();
      const second = await new NavigationBridge({ hal, provider: new GoalSeekingProvider() }).run(
        { x: 2, y: 0 },
        { signal: aborted.signal },
      );
      expect(second.status).toBe('stopped');
    });

    it('lets a new run start as soon as stop() resolves (a new click-to-goal)', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -2, y: 0, yaw: 0 } }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.2,
      });
      let second: Promise<unknown> | undefined;
      const off = bridge.on('result', () => {
        off();
        second = bridge.stop().then(() => bridge.run({ x: -1, y: 1 }));
      });
      const first = await bridge.run({ x: 2, y: 0 });
      expect(first.status).toBe('stopped');
      const next = (await second) as { status: string };
      expect(next.status).toBe('reached');
      expect(Math.hypot(hal.x + 1, hal.y - 1)).toBeLessThanOrEqual(0.1);
    });

    it('refuses a second run while one is in progress, and a goal that is not finite', async () => {
      const hal = await ready(new FakeHAL());
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const first = bridge.run({ x: 1, y: 0 });
      await expect(bridge.run({ x: 1, y: 0 })).rejects.toThrow('already in progress');
      await first;
      await expect(bridge.run({ x: Number.NaN, y: 0 })).rejects.toThrow('"goal"');
    });
  });
});
