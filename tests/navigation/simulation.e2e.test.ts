// End to end in simulation: the navigation bridge drives a SimulationHAL (the V1 cube moved as its
// firmware moves it) on each built-in map, from seeded starts to seeded goals, with the
// deterministic goal-seeking provider and the map as prior knowledge.
import {
  FrontierExplorationProvider,
  GoalSeekingProvider,
  NavigationBridge,
  OccupancyGrid,
} from '@hal/navigation';
import type { NavigationEvents } from '@hal/navigation';
import { BUILTIN_MAPS, SimulationHAL, World } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { scenarios } from './scenarios.js';

const SCENARIOS = scenarios(5);

describe('NavigationBridge on SimulationHAL', () => {
  it.each(SCENARIOS.map((s) => [`${s.map} #${s.seed}`, s] as const))(
    'reaches the goal without a collision on %s',
    async (_name, scenario) => {
      const world = new World({ map: scenario.map, seed: scenario.seed });
      const hal = new SimulationHAL({ world, start: scenario.start, clock: 'fast' });
      await hal.initialize();
      try {
        const bridge = new NavigationBridge({
          hal,
          provider: new GoalSeekingProvider(),
          map: world.map,
          maxCycles: 150,
        });
        const failures: NavigationEvents['result'][] = [];
        bridge.on('result', (e) => {
          if (!e.result.success) failures.push(e);
        });
        const outcome = await bridge.run(scenario.goal);
        expect(failures.filter((f) => f.result.code === 'COLLISION')).toEqual([]);
        expect(outcome.message).toMatch(/^reached/);
        expect(outcome.status).toBe('reached');
        // The simulated robot really is there (its odometry is its true pose).
        const robot = world.robots[0];
        expect(
          Math.hypot((robot?.x ?? 0) - scenario.goal.x, (robot?.y ?? 0) - scenario.goal.y),
        ).toBeLessThanOrEqual(0.1);
      } finally {
        await hal.cleanup();
      }
    },
  );

  it('reaches a goal on the obstacles map with no prior map, from the range sensors alone', async () => {
    const world = new World({ map: 'obstacles', seed: 5 });
    const hal = new SimulationHAL({ world, start: { x: -1.8, y: 0, yaw: 0 }, clock: 'fast' });
    await hal.initialize();
    try {
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        // Only the arena's walls are known; every obstacle has to be seen.
        map: { arena: BUILTIN_MAPS.obstacles.arena },
        maxLegM: 0.3,
        maxCycles: 200,
      });
      let collisions = 0;
      bridge.on('result', (e) => {
        if (e.result.code === 'COLLISION') collisions += 1;
      });
      const outcome = await bridge.run({ x: 1.8, y: 0.2 });
      expect(collisions).toBe(0);
      expect(outcome.status).toBe('reached');
      expect(bridge.grid.counts().occupied).toBeGreaterThan(0);
    } finally {
      await hal.cleanup();
    }
  });

  it('explores the room map with the frontier provider without a collision', async () => {
    const world = new World({ map: 'room', seed: 2 });
    const hal = new SimulationHAL({ world, clock: 'fast' });
    await hal.initialize();
    try {
      const grid = new OccupancyGrid();
      const bridge = new NavigationBridge({
        hal,
        grid,
        provider: new FrontierExplorationProvider(),
        map: { arena: BUILTIN_MAPS.room.arena, walls: BUILTIN_MAPS.room.walls },
        maxCycles: 60,
      });
      let collisions = 0;
      bridge.on('result', (e) => {
        if (e.result.code === 'COLLISION') collisions += 1;
      });
      const before = grid.counts().occupied;
      const outcome = await bridge.run(null);
      expect(collisions).toBe(0);
      expect(['reached', 'failed']).toContain(outcome.status);
      if (outcome.status === 'failed') expect(outcome.reason).toBe('MAX_CYCLES');
      // It found furniture the walls-only map did not show.
      expect(grid.counts().occupied).toBeGreaterThan(before);
    } finally {
      await hal.cleanup();
    }
  });
});
