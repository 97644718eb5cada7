import { SimulationHAL } from '@hal/simulation';
import type { BuiltinMapName, FrameSource, World } from '@hal/simulation';
import { HalError } from '@hal/types';
import { freeStart } from './free-start.js';
import { MAX_ROBOTS, robotColor, robotLabel } from './palette.js';

/** One of the demo's robots: its number, id, label and colour, and its own HAL. */
export interface DemoRobot {
  /** 1..{@link MAX_ROBOTS}; numbers are reused after a robot is removed. */
  readonly n: number;
  /** The robot's id in the world (`robot-N`). */
  readonly id: string;
  readonly label: string;
  readonly color: string;
  readonly hal: SimulationHAL;
}

export interface RosterOptions {
  world: World;
  /** Renders the robots' camera frames (the demo's Three.js renderer). */
  frameSource: FrameSource;
}

/** Footprint radius of the demo's robots, metres (the V1 cube, the world's default). */
const RADIUS_M = 0.07;

/**
 * The demo's simulated robots, all in one world, each driven by its own SimulationHAL, and which
 * of them is selected (the one the page's panels drive). Robots meet under the world's rules:
 * a robot that would touch another stops with outcome `collision`, like at a wall.
 */
export class RobotRoster {
  readonly world: World;
  readonly #frameSource: FrameSource;
  readonly #robots: DemoRobot[] = [];
  readonly #listeners = new Set<() => void>();
  #selected: DemoRobot | undefined;

  private constructor(options: RosterOptions) {
    this.world = options.world;
    this.#frameSource = options.frameSource;
  }

  /** A roster with one robot, at the map's first start, selected. */
  static async create(options: RosterOptions): Promise<RobotRoster> {
    const roster = new RobotRoster(options);
    await roster.add();
    return roster;
  }

  /** The robots, by number. */
  get robots(): readonly DemoRobot[] {
    return this.#robots;
  }

  /** The robot the panels drive. */
  get selected(): DemoRobot {
    const selected = this.#selected;
    if (selected === undefined) throw new HalError('NOT_READY', 'the roster has no robots');
    return selected;
  }

  /** The robot with this id; throws INVALID_PARAMETER if there is none. */
  robot(id: string): DemoRobot {
    const found = this.#robots.find((r) => r.id === id);
    if (found === undefined) throw new HalError('INVALID_PARAMETER', `no robot "${id}"`);
    return found;
  }

  /** Calls `listener` when robots are added, removed or selected; returns the unsubscriber. */
  onChange(listener: () => void): () => void {
    this.#listeners.add(listener);
    return () => this.#listeners.delete(listener);
  }

  /** Selects the robot with this id (throws INVALID_PARAMETER if there is none). */
  select(id: string): void {
    const robot = this.robot(id);
    if (robot === this.#selected) return;
    this.#selected = robot;
    this.#changed();
  }

  /**
   * Adds a robot with the lowest free number, at a free place (see {@link freeStart}), with its
   * own HAL, initialised. Fails with RANGE_EXCEEDED at {@link MAX_ROBOTS} or when no place is free.
   */
  async add(): Promise<DemoRobot> {
    if (this.#robots.length >= MAX_ROBOTS) {
      throw new HalError('RANGE_EXCEEDED', `the demo runs at most ${MAX_ROBOTS} robots`);
    }
    let n = 1;
    while (this.#robots.some((r) => r.n === n)) n += 1;
    const id = `robot-${n}`;
    this.#place(id);
    const hal = new SimulationHAL({
      world: this.world,
      robotId: id,
      clock: 'realtime',
      frameSource: this.#frameSource,
    });
    await hal.initialize();
    const robot: DemoRobot = { n, id, label: robotLabel(n), color: robotColor(n), hal };
    this.#robots.push(robot);
    this.#robots.sort((a, b) => a.n - b.n);
    this.#selected ??= robot;
    this.#changed();
    return robot;
  }

  /**
   * Removes a robot (its motion stops, its HAL is cleaned up). The last robot stays: removing it
   * fails with INVALID_PARAMETER. Removing the selected robot selects the first one left.
   */
  async remove(id: string): Promise<void> {
    const robot = this.robot(id);
    if (this.#robots.length === 1) {
      throw new HalError('INVALID_PARAMETER', 'the demo keeps at least one robot');
    }
    this.#robots.splice(this.#robots.indexOf(robot), 1);
    // The real-time ticker is shared: this HAL did not start it, so cleanup leaves it running.
    await robot.hal.cleanup();
    this.world.removeRobot(id);
    if (this.#selected === robot) this.#selected = this.#robots[0];
    this.#changed();
  }

  /**
   * Loads map `name` with the same robots: the first at the map's start, the others at free
   * places again (the world alone would stack extra robots on the map's few start poses).
   */
  resetWorld(name: BuiltinMapName): void {
    this.world.setMap(name);
    // setMap re-creates the robots in the world's order: the first keeps the map's first start.
    const others = this.world.robots.slice(1).map((r) => r.id);
    for (const id of others) this.world.removeRobot(id);
    for (const id of others) this.#place(id);
    this.#changed();
  }

  /** Adds the world's robot `id` at a free place; RANGE_EXCEEDED when there is none. */
  #place(id: string): void {
    const start = freeStart(this.world, RADIUS_M);
    if (start === undefined) {
      throw new HalError('RANGE_EXCEEDED', 'no free place for another robot on this map');
    }
    this.world.addRobot({ id, start, radius: RADIUS_M });
  }

  #changed(): void {
    for (const listener of this.#listeners) listener();
  }
}
