import { HalError, scoped, TypedEmitter, errorMessage } from '@hal/types';
import type { Logger, RobotConfig } from '@hal/types';
import { parseMap } from './map.js';
import type { WorldMap, WorldMapInput } from './map.js';
import { BUILTIN_MAPS } from './maps/index.js';
import type { BuiltinMapName } from './maps/index.js';
import { SeededRandom } from './rng.js';
import { SimRobot } from './robot/sim-robot.js';
import type { BodyErrorInput } from './robot/body-error.js';
import type { Contact, FreeSpace } from './robot/contact.js';
import { EventQueue } from './event-queue.js';
import { solidsOf } from './shapes.js';
import type { Solid } from './shapes.js';
import { RobotIndex } from './robot-index.js';
import { contactAmong, freeSpaceAmong, ROOM_HORIZON_US } from './world-contacts.js';

/** From this many robots on, the robots near a point are found through a {@link RobotIndex}. */
const INDEX_MIN_ROBOTS = 32;
/** An index is rebuilt when it is older than this, µs (it bounds how far robots have moved). */
const INDEX_MAX_AGE_US = 1_000_000;

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
  /**
   * Where a listener that throws is reported (namespace `hal:simulation:world`, level error); the
   * world goes on either way. Default silent.
   */
  logger?: Logger;
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
  /** How the body differs from the nominal one (see SimRobotOptions). Default none. */
  bodyError?: BodyErrorInput;
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
 *
 * Time moves from event to event, not tick to tick: each robot is due at its next event (a step
 * that must be checked for contact, the end of its motion, a host timeout), and the world takes
 * the events in time order (ties in the order the robots were added). Between its events a robot
 * takes only steps that cannot touch anything, and is brought up to the clock when read.
 */
export class World {
  readonly events: TypedEmitter<WorldEvents>;
  readonly random: SeededRandom;
  readonly tickUs: number;
  #map: WorldMap;
  #solids: Solid[];
  #robots: SimRobot[] = [];
  #nowUs = 0;
  #ticks = 0;
  #timer: ReturnType<typeof setInterval> | undefined;
  #speed = 0;
  readonly #queue = new EventQueue<SimRobot>();
  /** Robot id -> the id of the device that drives it (see {@link nameDevice}). */
  readonly #deviceNames = new Map<string, string>();
  #index: RobotIndex | undefined;

  constructor(options: WorldOptions = {}) {
    this.events = listenerSafeEmitter<WorldEvents>(options.logger, 'hal:simulation:world');
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

  /**
   * Names robot `robotId` by the device that drives it (a SimulationHAL's device id), for the
   * messages that speak of it: another robot's collision names `sim-b`, not `robot-2`.
   */
  nameDevice(robotId: string, deviceId: string): void {
    this.#deviceNames.set(robotId, deviceId);
  }

  /** The device id that drives robot `robotId`, else the robot's own id. */
  deviceName(robotId: string): string {
    return this.#deviceNames.get(robotId) ?? robotId;
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
      ...(options.bodyError === undefined ? {} : { bodyError: options.bodyError }),
    });
    robot.advanceTo(this.#nowUs);
    robot.setScheduler({
      nowUs: () => this.#nowUs,
      reschedule: (everyone) => this.#reschedule(robot, everyone),
    });
    robot.setContactTest(
      (x, y, r) => this.contactAt(x, y, r, robot),
      (x, y, r, atUs) => this.freeSpaceAt(x, y, r, robot, atUs),
    );
    this.#robots.push(robot);
    // The robots already moving measured their room without this one.
    this.#reschedule(robot, true);
    this.events.emit('robots', this.#robots);
    return robot;
  }

  /** Removes a robot (its motion stops). */
  removeRobot(id: string): void {
    const robot = this.robot(id);
    robot.stop();
    this.#queue.delete(robot);
    this.#robots = this.#robots.filter((r) => r !== robot);
    this.#index = undefined;
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
    this.#index = undefined;
    for (const robot of old) {
      robot.stop();
      this.#queue.delete(robot);
      this.addRobot({
        id: robot.id,
        config: robot.config,
        radius: robot.radius,
        ...(robot.bodyError === undefined ? {} : { bodyError: robot.bodyError }),
      });
    }
    this.events.emit('map', this.#map);
  }

  /**
   * What a disc at (x, y) of radius r touches (map solids and other robots), or undefined.
   * Robots check it before a step that could bring them into contact.
   */
  contactAt(x: number, y: number, r: number, self?: SimRobot): Contact | undefined {
    const index = this.#robotIndex(this.#nowUs);
    const near = index?.near(x, y, r + index.maxRadius + index.staleness(this.#nowUs));
    return contactAmong(x, y, r, this.#solids, this.#robots, self, this.#nowUs, near);
  }

  /**
   * How much room a disc at (x, y) of radius r has at `atUs`: how far it can move and touch no
   * solid, and until when no other robot can touch it.
   */
  freeSpaceAt(x: number, y: number, r: number, self: SimRobot, atUs: number): FreeSpace {
    const index = this.#robotIndex(atUs);
    // A robot farther than this cannot reach `self` within the horizon, whatever either does.
    const reach =
      r +
      (index?.maxRadius ?? 0) +
      ((self.maxSpeedMps + (index?.maxSpeedMps ?? 0)) * ROOM_HORIZON_US) / 1e6 +
      (index?.staleness(atUs) ?? 0);
    const near = index?.near(x, y, reach);
    return freeSpaceAmong(x, y, r, this.#solids, this.#robots, self, atUs, near);
  }

  /** The index of robot positions, rebuilt when missing or too old; none for few robots. */
  #robotIndex(nowUs: number): RobotIndex | undefined {
    if (this.#robots.length < INDEX_MIN_ROBOTS) return undefined;
    const index = this.#index;
    if (index === undefined || nowUs < index.builtUs || nowUs - index.builtUs > INDEX_MAX_AGE_US) {
      this.#index = new RobotIndex(this.#robots, this.#nowUs);
    }
    return this.#index;
  }

  /** A robot's next event may have moved; `everyone`: every robot must measure its room again. */
  #reschedule(robot: SimRobot, everyone: boolean): void {
    if (everyone) {
      this.#index = undefined;
      for (const other of this.#robots) {
        other.invalidateRoom();
        this.#queue.set(other, other.nextEventUs);
      }
    }
    if (this.#robots.includes(robot)) this.#queue.set(robot, robot.nextEventUs);
  }

  /** Takes every robot event due by `targetUs`, in time order, then sets the clock to it. */
  #advanceTo(targetUs: number): void {
    const queue = this.#queue;
    while (queue.peekTime() <= targetUs) {
      const robot = queue.peek() as SimRobot;
      const atUs = queue.peekTime();
      if (atUs > this.#nowUs) this.#nowUs = atUs;
      const wasRunning = robot.running;
      robot.advanceTo(this.#nowUs);
      const next = robot.nextEventUs;
      if (next <= this.#nowUs) {
        throw new Error(`robot "${robot.id}" did not get past its event at ${this.#nowUs} µs`);
      }
      queue.set(robot, next);
      if (wasRunning && !robot.running) {
        const motion = robot.motion;
        if (motion?.outcome === 'collision' && motion.contact !== undefined) {
          this.events.emit('collision', { robotId: robot.id, contact: motion.contact });
        }
      }
    }
    this.#nowUs = targetUs;
  }

  /** Advances the clock by one tick, taking the robot events due by then. */
  step(): void {
    const next = this.#nowUs + this.tickUs;
    this.#advanceTo(next);
    this.#ticks += 1;
    this.events.emit('tick', next);
  }

  /**
   * Advances the clock by `us` microseconds (rounded up to whole ticks). With no `tick`
   * listener it goes there in one go, from event to event; with one, tick by tick.
   */
  advance(us: number): void {
    if (!(us > 0)) return;
    const ticks = Math.ceil(us / this.tickUs);
    if (this.events.has('tick')) {
      for (let i = 0; i < ticks; i += 1) this.step();
      return;
    }
    this.#advanceTo(this.#nowUs + ticks * this.tickUs);
    this.#ticks += ticks;
    this.events.emit('tick', this.#nowUs);
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

/**
 * An emitter whose throwing listener is logged (at error level) and changes nothing else: the
 * other listeners still run and the step that emitted goes on.
 */
export function listenerSafeEmitter<Events extends { [K in keyof Events]: unknown }>(
  logger: Logger | undefined,
  namespace: string,
): TypedEmitter<Events> {
  if (logger === undefined) return new TypedEmitter<Events>();
  const log = scoped(logger, namespace);
  return new TypedEmitter<Events>((event, error) =>
    log.error('event listener threw', {
      event,
      error: errorMessage(error),
    }),
  );
}
