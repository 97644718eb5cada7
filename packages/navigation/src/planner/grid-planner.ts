import { cellCentre, worldToCell } from '../grid/geometry.js';
import type { Cell, GridSpec, Point } from '../grid/geometry.js';
import { AStarSearch } from './astar.js';
import type { GridSearchStatus } from './astar.js';
import { simplifyPath } from './line-of-sight.js';
import type { ObstacleMap } from './obstacle-map.js';

/** A planned route in the world, metres. */
export interface PathPlan {
  /** How the search ended (see {@link GridSearchStatus}); waypoints are empty unless `found`. */
  status: GridSearchStatus;
  /**
   * Cell centres (metres) from the start cell to the goal cell, simplified by line of sight when
   * asked (the default). The first is the centre of the start cell, the last the goal cell's.
   */
  waypoints: Point[];
  /** Length of the waypoint polyline, metres. */
  lengthM: number;
  /** Cost of the unsimplified A* path, metres (octile). */
  costM: number;
  /** Cells of the unsimplified A* path. */
  cells: Cell[];
  /** Nodes the search expanded. */
  expanded: number;
  /** The start and goal cells, when they lie on the grid. */
  startCell?: Cell;
  goalCell?: Cell;
}

/** Options of one {@link GridPlanner.plan} call. */
export interface PlanOptions {
  /** Shorten the path by line of sight. Default true. */
  simplify?: boolean;
}

/** Plans routes between world points on an {@link ObstacleMap} laid out by a {@link GridSpec}. */
export class GridPlanner {
  readonly spec: GridSpec;
  readonly map: ObstacleMap;
  readonly #search: AStarSearch;

  constructor(spec: GridSpec, map: ObstacleMap) {
    if (map.width !== spec.width || map.height !== spec.height) {
      throw new RangeError(
        `the obstacle map is ${map.width}x${map.height} cells but the grid is ${spec.width}x${spec.height}`,
      );
    }
    this.spec = spec;
    this.map = map;
    this.#search = new AStarSearch(map);
  }

  /** Plans from world point `from` to world point `to`. Never throws for unreachable goals. */
  plan(from: Point, to: Point, options: PlanOptions = {}): PathPlan {
    const startCell = worldToCell(this.spec, from.x, from.y);
    const goalCell = worldToCell(this.spec, to.x, to.y);
    const base = { waypoints: [], lengthM: 0, costM: 0, cells: [], expanded: 0 };
    if (startCell === undefined || goalCell === undefined) {
      const plan: PathPlan = { status: 'out-of-bounds', ...base };
      if (startCell !== undefined) plan.startCell = startCell;
      if (goalCell !== undefined) plan.goalCell = goalCell;
      return plan;
    }
    const result = this.#search.search(startCell.cx, startCell.cy, goalCell.cx, goalCell.cy);
    if (result.status !== 'found') {
      return { status: result.status, ...base, expanded: result.expanded, startCell, goalCell };
    }
    const w = this.spec.width;
    const kept = options.simplify === false ? result.cells : simplifyPath(this.map, result.cells);
    const toCell = (i: number): Cell => ({ cx: i % w, cy: Math.floor(i / w) });
    const waypoints = kept.map((i) => {
      const c = toCell(i);
      return cellCentre(this.spec, c.cx, c.cy);
    });
    let lengthM = 0;
    for (let k = 1; k < waypoints.length; k += 1) {
      const a = waypoints[k - 1] as Point;
      const b = waypoints[k] as Point;
      lengthM += Math.hypot(b.x - a.x, b.y - a.y);
    }
    return {
      status: 'found',
      waypoints,
      lengthM,
      costM: result.cost * this.spec.resolutionM,
      cells: result.cells.map(toCell),
      expanded: result.expanded,
      startCell,
      goalCell,
    };
  }
}
