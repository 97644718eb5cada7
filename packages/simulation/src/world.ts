import { HalError } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import { parseMap } from './map.js';
import type { WorldMap, WorldMapInput } from './map.js';
import { BUILTIN_MAPS } from './maps/index.js';
import type { BuiltinMapName } from './maps/index.js';
import { SeededRandom } from './rng.js';
import { SimRobot } from './robot/sim-robot.js';
import type { Contact } from './robot/contact.js';
import { discContact, solidsOf } from './shapes.js';
import type { Solid } from './shapes.js';

/** Side of a cell of the robot grid, metres. */
const GRID_CELL_M = 0.5;
/** Below this many robots, contact tests check every robot (cheaper than a grid). */
const GRID_MIN_ROBOTS = 12;

/** Listener bookkeeping for a few named events (no Node dependency, works in the browser). */
export class Emitter<Events extends Record<string, unknown>> {
  readonly #listeners = new Map<keyof Events, Set<(payload: never) => void>>();

  /** Calls `listener` on every `event`; returns the function that unsubscribes it. */
  on<E extends keyof Events>(event: E, listener: (payload: Events[E]) => void): () => void {
    let set = this.#listeners.get(event);
    if (set === undefined) {
      set = new Set();
      this.#listeners.set(event, set);
    }
    set.add(listener as (payload: never) => void);
    return () => set.delete(listener as (payload: never) => void);
  }

  emit<E extends keyof Events>(event: E, payload: Events[E]): void {
    const set = this.#listeners.get(event);
    if (set === undefined) return;
    for (const listener of set) (listener as (p: Events[E]) => void)(payload);
  }
}

/** What a {@link World} reports to whoever listens (a UI, a recorder, a test). */
export interface WorldEvents extends Record<string, unknown> {
  /** The clock advanced; payload: simulated time, µs. */
  tick: number;
  /** A robot touched something and stopped. */
  collision: { robotId: string; contact: Contact };
  /** The map was replaced (robots went back to their starts). */
  map: WorldMap;
  /** A robot was added or removed. */
  robots: readonly SimRobot[];
}

export interface WorldOptions {
  /** A map (checked), or the name of a built-in one. Default `empty`. */
  map?: WorldMapInput | BuiltinMapName;
  /** Seed of the world's only random source. Default 1. */
  seed?: number;
  /** Simulated time per step, µs. Default 1000 (1 ms). */
  tickUs?: number;
}

export interface AddRobotOptions {
  /** Unique id; default `robot-N`. */
  id?: string;
  /** Geometry and limits; default the V1 robot. */
  config?: RobotConfig;
  /** Start pose, metres and radians; default the map's start for this robot's index. */
  start?: { x: number; y: number; yaw: number };
  /** Footprint radius, metres. Default 0.07. */
  radius?: number;
}

/** Options of {@link World.startRealtime}. */
export interface RealtimeOptions {
  /** Simulated seconds per wall-clock second. Default 1 (real time). */
  speed?: number;
  /** How often the ticker runs, ms. Default 16. */
  intervalMs?: number;
  /** Wall clock, ms. Default `performance.now`. */
  now?: () => number;
}

function resolveMap(map: WorldOptions['map']): WorldMap {
  if (map === undefined) return BUILTIN_MAPS.empty;
  if (typeof map === 'string') {
    const found = (BUILTIN_MAPS as Record<string, WorldMap | undefined>)[map];
    if (found === undefined) {
      throw new HalError(
        'INVALID_PARAMETER',
        `map "${map}" is not a built-in map (${Object.keys(BUILTIN_MAPS).join(', ')})`,
      );
    }
    return found;
  }
  return parseMap(map);
}

/**
 * A deterministic world: a map, its solids, robots, and a simulated clock that only moves when
 * told to (`step`, `advance`, `advanceUntil`) or by a real-time ticker (`startRealtime`).
 */
export class World {
  readonly events = new Emitter<WorldEvents>();
  readonly random: SeededRandom;
  readonly tickUs: number;
  #map: WorldMap;
  #solids: Solid[];
  #robots: SimRobot[] = [];
  #nowUs = 0;
  #ticks = 0;
  #timer: ReturnType<typeof setInterval> | undefined;
  #speed = 0;
  #grid: Map<number, number[]> | undefined;

  constructor(options: WorldOptions = {}) {
    this.random = new SeededRandom(options.seed ?? 1);
    this.tickUs = options.tickUs ?? 1000;
    if (!Number.isInteger(this.tickUs) || this.tickUs < 1) {
      throw new HalError('INVALID_PARAMETER', `"tickUs" must be a whole number >= 1`);
    }
    this.#map = resolveMap(options.map);
    this.#solids = solidsOf(this.#map);
  }

  get map(): WorldMap {
    return this.#map;
  }
  /** The map's solids (arena walls, walls, obstacles). */
  get solids(): readonly Solid[] {
    return this.#solids;
  }
  get robots(): readonly SimRobot[] {
    return this.#robots;
  }
  /** Simulated time, µs. */
  get nowUs(): number {
    return this.#nowUs;
  }
  /** Steps taken since the world was made. */
  get ticks(): number {
    return this.#ticks;
  }
  /** The real-time ticker's speed (simulated s per wall s), 0 when it is not running. */
  get realtimeSpeed(): number {
    return this.#speed;
  }

  /** The robot with this id; throws INVALID_PARAMETER if there is none. */
  robot(id: string): SimRobot {
    const found = this.#robots.find((r) => r.id === id);
    if (found === undefined) throw new HalError('INVALID_PARAMETER', `no robot "${id}"`);
    return found;
  }

  /** Adds a robot at its start pose. */
  addRobot(options: AddRobotOptions = {}): SimRobot {
    const index = this.#robots.length;
    const id = options.id ?? `robot-${index + 1}`;
    if (this.#robots.some((r) => r.id === id)) {
      throw new HalError('INVALID_PARAMETER', `a robot "${id}" already exists`);
    }
    const starts = this.#map.starts;
    const start = options.start ?? starts[index % starts.length] ?? { x: 0, y: 0, yaw: 0 };
    const robot = new SimRobot({
      id,
      start,
      ...(options.config === undefined ? {} : { config: options.config }),
      ...(options.radius === undefined ? {} : { radius: options.radius }),
    });
    robot.advanceTo(this.#nowUs);
    robot.setContactTest((x, y, r) => this.contactAt(x, y, r, robot));
    this.#robots.push(robot);
    this.events.emit('robots', this.#robots);
    return robot;
  }

  /** Removes a robot (its motion stops). */
  removeRobot(id: string): void {
    const robot = this.robot(id);
    robot.stop();
    this.#robots = this.#robots.filter((r) => r !== robot);
    this.events.emit('robots', this.#robots);
  }

  /**
   * Replaces the map. Every robot stops and goes back to a start pose of the new map (robots are
   * re-created with the same ids and configurations; hold robots by id, not by reference).
   */
  setMap(map: WorldMapInput | BuiltinMapName): void {
    this.#map = resolveMap(map);
    this.#solids = solidsOf(this.#map);
    const old = this.#robots;
    this.#robots = [];
    for (const robot of old) {
      robot.stop();
      this.addRobot({ id: robot.id, config: robot.config, radius: robot.radius });
    }
    this.events.emit('map', this.#map);
  }

  /**
   * What a disc at (x, y) of radius r touches (map solids and other robots), or undefined.
   * Used by robots on every step they move.
   */
  contactAt(x: number, y: number, r: number, self?: SimRobot): Contact | undefined {
    for (const solid of this.#solids) {
      const point = discContact(x, y, r, solid);
      if (point !== undefined) return { point, role: solid.role, index: solid.index };
    }
    const grid = this.#grid;
    if (grid === undefined) {
      for (let i = 0; i < this.#robots.length; i += 1) {
        const hit = this.#robotContact(x, y, r, i, self);
        if (hit !== undefined) return hit;
      }
      return undefined;
    }
    const cx = Math.floor(x / GRID_CELL_M);
    const cy = Math.floor(y / GRID_CELL_M);
    for (let gx = cx - 1; gx <= cx + 1; gx += 1) {
      for (let gy = cy - 1; gy <= cy + 1; gy += 1) {
        const cell = grid.get(gx * 65_536 + gy);
        if (cell === undefined) continue;
        for (const i of cell) {
          const hit = this.#robotContact(x, y, r, i, self);
          if (hit !== undefined) return hit;
        }
      }
    }
    return undefined;
  }

  #robotContact(
    x: number,
    y: number,
    r: number,
    i: number,
    self: SimRobot | undefined,
  ): Contact | undefined {
    const other = this.#robots[i] as SimRobot;
    if (other === self) return undefined;
    const dx = x - other.x;
    const dy = y - other.y;
    const reach = r + other.radius;
    const d2 = dx * dx + dy * dy;
    if (d2 >= reach * reach) return undefined;
    const d = Math.sqrt(d2) || 1;
    return {
      point: { x: other.x + (dx / d) * other.radius, y: other.y + (dy / d) * other.radius },
      role: 'robot',
      index: i,
      robotId: other.id,
    };
  }

  /**
   * With many robots, a grid of robot indices by cell, rebuilt every tick, so a contact test
   * looks only at the robots in the nine cells around it. A robot moves far less than a cell per
   * tick, and no robot is wider than a cell, so nothing in reach is missed.
   */
  #buildGrid(): void {
    const robots = this.#robots;
    if (robots.length < GRID_MIN_ROBOTS || robots.some((r) => r.radius * 2 > GRID_CELL_M / 2)) {
      this.#grid = undefined;
      return;
    }
    const grid = new Map<number, number[]>();
    for (let i = 0; i < robots.length; i += 1) {
      const robot = robots[i] as SimRobot;
      const key = Math.floor(robot.x / GRID_CELL_M) * 65_536 + Math.floor(robot.y / GRID_CELL_M);
      const cell = grid.get(key);
      if (cell === undefined) grid.set(key, [i]);
      else cell.push(i);
    }
    this.#grid = grid;
  }

  /** Advances the clock by one tick and moves every robot. */
  step(): void {
    const next = this.#nowUs + this.tickUs;
    const robots = this.#robots;
    this.#buildGrid();
    for (let i = 0; i < robots.length; i += 1) {
      const robot = robots[i] as SimRobot;
      const wasRunning = robot.running;
      robot.advanceTo(next);
      if (wasRunning && !robot.running) {
        const contact = robot.motion?.contact;
        if (robot.motion?.outcome === 'collision' && contact !== undefined) {
          this.events.emit('collision', { robotId: robot.id, contact });
        }
      }
    }
    this.#grid = undefined;
    this.#nowUs = next;
    this.#ticks += 1;
    this.events.emit('tick', next);
  }

  /** Advances the clock by `us` microseconds (rounded up to whole ticks). */
  advance(us: number): void {
    const target = this.#nowUs + us;
    while (this.#nowUs < target) this.step();
  }

  /**
   * Steps until `done()` is true or `maxUs` of simulated time have passed. Returns whether
   * `done()` became true.
   */
  advanceUntil(done: () => boolean, maxUs: number): boolean {
    const limit = this.#nowUs + maxUs;
    while (!done()) {
      if (this.#nowUs >= limit) return false;
      this.step();
    }
    return true;
  }

  /**
   * Runs the clock against the wall clock (the demo's mode): every `intervalMs` it advances by
   * the wall time elapsed times `speed`. Calling it again changes the speed.
   */
  startRealtime(options: RealtimeOptions = {}): void {
    const speed = options.speed ?? 1;
    if (!(speed > 0) || !Number.isFinite(speed)) {
      throw new HalError('RANGE_EXCEEDED', `"speed" must be a finite number > 0, got ${speed}`);
    }
    this.stopRealtime();
    const now = options.now ?? (() => performance.now());
    let last = now();
    let owedUs = 0;
    this.#speed = speed;
    this.#timer = setInterval(() => {
      const t = now();
      // A stalled tab must not make the world jump by minutes: at most 250 ms per beat.
      owedUs += Math.min(t - last, 250) * 1000 * this.#speed;
      last = t;
      while (owedUs >= this.tickUs) {
        this.step();
        owedUs -= this.tickUs;
      }
    }, options.intervalMs ?? 16);
  }

  /** Stops the real-time ticker (the clock then moves only when told to). */
  stopRealtime(): void {
    if (this.#timer !== undefined) clearInterval(this.#timer);
    this.#timer = undefined;
    this.#speed = 0;
  }
}
