import { describe, expect, it } from 'vitest';
import { findFrontier } from '../grid/frontier.js';
import { OccupancyGrid } from '../grid/occupancy-grid.js';
import { FrontierExplorationProvider, GoalSeekingProvider } from './deterministic.js';
import type { DecisionContext } from './provider.js';

function context(grid: OccupancyGrid, overrides: Partial<DecisionContext> = {}): DecisionContext {
  return {
    cycle: 1,
    goal: { x: 1, y: 1 },
    goalToleranceM: 0.1,
    pose: { x: 0, y: 0, yaw: 0 },
    grid,
    ...overrides,
  };
}

describe('GoalSeekingProvider', () => {
  it('moves to the goal until within tolerance, then stops with goal_reached', async () => {
    const provider = new GoalSeekingProvider();
    const grid = new OccupancyGrid();
    expect((await provider.decide(context(grid))).action).toEqual({ type: 'MOVE_TO', x: 1, y: 1 });
    const there = await provider.decide(context(grid, { pose: { x: 0.95, y: 1.02, yaw: 0 } }));
    expect(there).toMatchObject({ action: { type: 'STOP' }, goal_reached: true });
  });

  it('explores when there is no goal', async () => {
    const decision = await new GoalSeekingProvider().decide(
      context(new OccupancyGrid(), { goal: null }),
    );
    expect(decision.action).toEqual({ type: 'EXPLORE' });
  });
});

describe('FrontierExplorationProvider', () => {
  it('heads for the nearest free cell next to unknown space', async () => {
    const grid = new OccupancyGrid();
    // Known free: a 1 m square around the origin; everything else unknown.
    for (let cy = 40; cy < 60; cy += 1)
      for (let cx = 40; cx < 60; cx += 1) grid.setLogOdds(cx, cy, -2);
    const decision = await new FrontierExplorationProvider().decide(context(grid, { goal: null }));
    expect(decision.action.type).toBe('MOVE_TO');
    if (decision.action.type !== 'MOVE_TO') return;
    // The frontier is the edge of the known square.
    const edge = Math.max(Math.abs(decision.action.x), Math.abs(decision.action.y));
    expect(edge).toBeCloseTo(0.475, 6);
  });

  it('stops, exploration done, when no frontier is reachable', async () => {
    const grid = new OccupancyGrid();
    grid.seedFromMap({ arena: { width: 5, height: 5 } });
    const decision = await new FrontierExplorationProvider().decide(context(grid, { goal: null }));
    expect(decision).toMatchObject({ action: { type: 'STOP' }, goal_reached: true });
  });

  it('goes to the goal once the route there is known free', async () => {
    const grid = new OccupancyGrid();
    grid.seedFromMap({ arena: { width: 5, height: 5 } });
    const decision = await new FrontierExplorationProvider().decide(context(grid));
    expect(decision.action).toEqual({ type: 'MOVE_TO', x: 1, y: 1 });
  });

  it('gives up on a frontier after the configured number of attempts', async () => {
    const grid = new OccupancyGrid();
    for (let cy = 45; cy < 55; cy += 1)
      for (let cx = 45; cx < 55; cx += 1) grid.setLogOdds(cx, cy, -2);
    const provider = new FrontierExplorationProvider({ attemptsPerFrontier: 2 });
    const targets = [];
    for (let k = 0; k < 4; k += 1) {
      const d = await provider.decide(context(grid, { goal: null }));
      if (d.action.type === 'MOVE_TO') targets.push(`${d.action.x},${d.action.y}`);
    }
    expect(targets[0]).toBe(targets[1]);
    expect(targets[2]).not.toBe(targets[0]);
  });
});

describe('findFrontier', () => {
  it('finds nothing from a point off the grid', () => {
    expect(findFrontier(new OccupancyGrid(), { x: 10, y: 0 })).toBeUndefined();
  });
});
