// The example in packages/navigation/README.md and docs/navigation.md, as a test: if it stops
// working, this fails.
import { GoalSeekingProvider, NavigationBridge, OccupancyGrid } from '@hal/navigation';
import { SimulationHAL, World } from '@hal/simulation';
import { expect, it } from 'vitest';

it('runs the README example: drive to a goal on the obstacles map', async () => {
  const world = new World({ map: 'obstacles' });
  const hal = new SimulationHAL({ world });
  await hal.initialize();

  const bridge = new NavigationBridge({
    hal,
    provider: new GoalSeekingProvider(),
    grid: OccupancyGrid.fromMap(world.map),
  });
  const routes: number[] = [];
  bridge.on('path', ({ plan }) => routes.push(plan.waypoints.length));
  const outcome = await bridge.run({ x: 1.8, y: 0.2 });
  // outcome.status: 'reached' | 'stopped' | 'failed'; outcome.reason says why.

  expect(outcome.status).toBe('reached');
  expect(outcome.reason).toBe('GOAL_REACHED');
  expect(routes.length).toBeGreaterThan(0);
  await hal.cleanup();
});
