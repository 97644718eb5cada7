import { findFrontier } from '../grid/frontier.js';
import { distance } from '../grid/geometry.js';
import type { Point } from '../grid/geometry.js';
import type { DecisionContext, DecisionProvider } from './provider.js';
import type { NavigationDecision } from './schema.js';

const f2 = (v: number) => v.toFixed(2);

function atGoal(context: DecisionContext): boolean {
  const { goal, pose, goalToleranceM } = context;
  return goal !== null && distance(goal, pose) <= goalToleranceM;
}

/**
 * Goal seeking with A*: MOVE_TO the goal (the bridge follows the planned route one leg per
 * cycle) until within tolerance, then STOP with `goal_reached`. With no goal it explores.
 * Needs no network and no camera: for offline use, tests and demos.
 */
export class GoalSeekingProvider implements DecisionProvider {
  readonly name = 'goal-seeking';

  async decide(context: DecisionContext): Promise<NavigationDecision> {
    const { goal, pose } = context;
    if (goal === null) {
      return {
        reasoning: 'No goal given: exploring.',
        action: { type: 'EXPLORE' },
        goal_reached: false,
      };
    }
    if (atGoal(context)) {
      return {
        reasoning: `At the goal (${f2(goal.x)}, ${f2(goal.y)}).`,
        action: { type: 'STOP' },
        goal_reached: true,
      };
    }
    const away = distance(goal, pose);
    return {
      reasoning: `Goal ${f2(away)} m away: following the A* route to (${f2(goal.x)}, ${f2(goal.y)}).`,
      action: { type: 'MOVE_TO', x: goal.x, y: goal.y },
      goal_reached: false,
    };
  }
}

/** Options of a {@link FrontierExplorationProvider}. */
export interface FrontierExplorationOptions {
  /** Ignore frontiers nearer than this, metres. Default 0.2. */
  minDistanceM?: number;
  /** Give up on a frontier after this many decisions aimed at it. Default 4. */
  attemptsPerFrontier?: number;
}

/**
 * Frontier exploration: MOVE_TO the nearest reachable free cell that borders unknown space,
 * until none is left (then STOP: the reachable space is explored). When a goal is given and the
 * route to it runs through known free space only, it goes to the goal instead, and stops there.
 */
export class FrontierExplorationProvider implements DecisionProvider {
  readonly name = 'frontier-exploration';
  readonly #minDistanceM: number;
  readonly #attempts: number;
  readonly #tried = new Map<string, number>();
  readonly #abandoned: Point[] = [];

  constructor(options: FrontierExplorationOptions = {}) {
    this.#minDistanceM = options.minDistanceM ?? 0.2;
    this.#attempts = options.attemptsPerFrontier ?? 4;
  }

  async decide(context: DecisionContext): Promise<NavigationDecision> {
    const { goal, pose, grid } = context;
    if (goal !== null) {
      if (atGoal(context)) {
        return { reasoning: 'At the goal.', action: { type: 'STOP' }, goal_reached: true };
      }
      const plan = grid.plan(pose, goal);
      const known =
        plan.status === 'found' && plan.cells.every((c) => grid.stateOf(c.cx, c.cy) === 'free');
      if (known) {
        return {
          reasoning: 'The route to the goal runs through known free space: going to the goal.',
          action: { type: 'MOVE_TO', x: goal.x, y: goal.y },
          goal_reached: false,
        };
      }
    }
    for (;;) {
      const frontier = findFrontier(grid, pose, {
        minDistanceM: this.#minDistanceM,
        exclude: this.#abandoned,
      });
      if (frontier === undefined) {
        return {
          reasoning: 'No reachable frontier is left: the reachable space is explored.',
          action: { type: 'STOP' },
          goal_reached: goal === null,
        };
      }
      const key = `${f2(frontier.target.x)},${f2(frontier.target.y)}`;
      const tries = (this.#tried.get(key) ?? 0) + 1;
      if (tries > this.#attempts) {
        this.#abandoned.push(frontier.target);
        continue;
      }
      this.#tried.set(key, tries);
      return {
        reasoning: `Exploring: nearest frontier at (${f2(frontier.target.x)}, ${f2(
          frontier.target.y,
        )}), ${f2(frontier.distanceM)} m away.`,
        action: { type: 'MOVE_TO', x: frontier.target.x, y: frontier.target.y },
        goal_reached: false,
      };
    }
  }
}
