// What happens to the robot, as it happens: e-stops (by whom, why) and resets, collisions, guard
// stops, the link lost and back, low battery and faults, kept as a short history (robot://events)
// and told to listeners; and the robot's log lines. The HAL has no event emitter of its own: the
// safety status and the link are read at a steady rate, and the rest comes from the sources the
// app wires (the guard's events, the simulator's collisions, the HAL's log).
import type { HardwareAbstractionLayer, LogLevel, SafetyStatus } from '@hal/types';

/** What happened. */
export type RobotEventType =
  | 'emergency_stop'
  | 'reset'
  | 'collision'
  | 'guard_stop'
  | 'link_lost'
  | 'link_back'
  | 'low_battery'
  | 'fault';

/** One thing that happened to the robot. */
export interface RobotEvent {
  /** Counts up from 1 over the feed's life. */
  seq: number;
  /** When it was seen, ISO 8601. */
  at: string;
  type: RobotEventType;
  /** What happened, in a sentence. */
  message: string;
  /** Who did it, where known: `mcp-client` (a tool call through this server) or `elsewhere`. */
  by?: 'mcp-client' | 'elsewhere';
  /** The reason given (an e-stop's). */
  reason?: string;
  details?: Record<string, unknown>;
}

/** One line of the robot's log. */
export interface RobotLogLine {
  level: LogLevel;
  /** Where it comes from: `robot` (the HAL's log), `events`, `guard`. */
  logger: string;
  message: string;
}

/** An event of @hal/perception's guard, as far as the feed reads it. */
export interface GuardEventLike {
  type: string;
  message?: string;
  stop?: { distanceM?: number; source?: string; motion?: string; when?: string };
}

/** Where events come from besides the HAL's safety status. */
export interface RobotEventSources {
  /** The link's state now (`connected`, `lost`, ...), for a robot over a link. */
  link?: () => string;
  /** The guard (`GuardedHAL` of @hal/perception): its stops and warnings. */
  guard?: { onEvent(listener: (event: GuardEventLike) => void): () => void };
  /** Collisions the robot feels (the simulator's contacts): subscribes, answers the unsubscribe. */
  collisions?: (
    listener: (message: string, details?: Record<string, unknown>) => void,
  ) => () => void;
  /** The HAL's log lines: subscribes, answers the unsubscribe. */
  logs?: (listener: (line: { level: LogLevel; message: string }) => void) => () => void;
}

/** How the feed reads and keeps. */
export interface RobotEventsOptions {
  /** How often the safety status and the link are read, ms. Default 200. */
  pollMs?: number;
  /** How many events are kept. Default 50. */
  keep?: number;
  /** A measured battery below this percent is low. Default 20. */
  lowBatteryPercent?: number;
}

const LEVEL_OF: Record<RobotEventType, LogLevel> = {
  emergency_stop: 'warn',
  reset: 'info',
  collision: 'warn',
  guard_stop: 'info',
  link_lost: 'error',
  link_back: 'info',
  low_battery: 'warn',
  fault: 'error',
};

/** The feed of one robot's events, shared by every server that serves it. */
export class RobotEvents {
  readonly #hal: HardwareAbstractionLayer;
  readonly #sources: RobotEventSources;
  readonly #pollMs: number;
  readonly #keep: number;
  readonly #lowPercent: number;
  readonly #events: RobotEvent[] = [];
  readonly #listeners = new Set<(event: RobotEvent) => void>();
  readonly #logListeners = new Set<(line: RobotLogLine) => void>();
  #seq = 0;
  #users = 0;
  #timer: ReturnType<typeof setInterval> | undefined;
  #unsubscribe: Array<() => void> = [];
  #latched: boolean | undefined;
  #errors = new Set<string>();
  #low = false;
  #link: string | undefined;
  /** E-stops and resets asked for by an MCP client, not yet seen in the status. */
  #pending = { estop: 0, reset: 0 };
  /** Aborted at the next stop of the robot (a stop or e-stop call, an e-stop seen latching). */
  #stops = new AbortController();

  constructor(
    hal: HardwareAbstractionLayer,
    sources: RobotEventSources = {},
    options: RobotEventsOptions = {},
  ) {
    this.#hal = hal;
    this.#sources = sources;
    this.#pollMs = options.pollMs ?? 200;
    this.#keep = options.keep ?? 50;
    this.#lowPercent = options.lowBatteryPercent ?? 20;
  }

  /** Starts watching (once for any number of users); answers the release. */
  open(): () => void {
    this.#users += 1;
    if (this.#users === 1) this.#start();
    let released = false;
    return () => {
      if (released) return;
      released = true;
      this.#users -= 1;
      if (this.#users === 0) this.#stop();
    };
  }

  /** The events kept, oldest first. */
  recent(): RobotEvent[] {
    return this.#events.map((e) => ({ ...e }));
  }

  /** Listens to events; answers the unsubscribe. */
  on(listener: (event: RobotEvent) => void): () => void {
    this.#listeners.add(listener);
    return () => this.#listeners.delete(listener);
  }

  /** Listens to log lines (events among them); answers the unsubscribe. */
  onLog(listener: (line: RobotLogLine) => void): () => void {
    this.#logListeners.add(listener);
    return () => this.#logListeners.delete(listener);
  }

  /** A log line of the robot, to every log listener. */
  log(line: RobotLogLine): void {
    for (const listener of this.#logListeners) {
      try {
        listener(line);
      } catch {
        // a listener that throws does not stop the others
      }
    }
  }

  /** An MCP client asked for an e-stop (or a reset): the latch change it brings is its own. */
  expect(what: 'estop' | 'reset'): void {
    this.#pending[what] += 1;
  }

  /**
   * The signal of the robot's next stop: a stop or an e-stop through any server of the robot
   * ({@link stopped}), or an e-stop seen latching from elsewhere. What waits on a person's
   * answer gives up at it.
   */
  nextStop(): AbortSignal {
    return this.#stops.signal;
  }

  /** The robot was told to stop: whatever waits for {@link nextStop} gives up. */
  stopped(): void {
    this.#stops.abort();
    this.#stops = new AbortController();
  }

  /** Reads the status now (after a safety call), rather than at the next tick. */
  check(): void {
    this.#poll();
  }

  /** Adds an event: kept, told to listeners, logged. */
  add(event: Omit<RobotEvent, 'seq' | 'at'>): RobotEvent {
    this.#seq += 1;
    const full: RobotEvent = { seq: this.#seq, at: new Date().toISOString(), ...event };
    this.#events.push(full);
    if (this.#events.length > this.#keep) this.#events.shift();
    for (const listener of this.#listeners) {
      try {
        listener({ ...full });
      } catch {
        // as above
      }
    }
    this.log({ level: LEVEL_OF[event.type], logger: 'events', message: event.message });
    return full;
  }

  #start(): void {
    const status = this.#status();
    this.#latched = status?.emergencyStopped;
    this.#errors = new Set(status?.errors ?? []);
    this.#low = status !== undefined && this.#isLow(status);
    this.#link = this.#sources.link?.();
    const { guard, collisions, logs } = this.#sources;
    if (guard !== undefined) this.#unsubscribe.push(guard.onEvent((e) => this.#guardEvent(e)));
    if (collisions !== undefined) {
      this.#unsubscribe.push(
        collisions((message, details) =>
          this.add({ type: 'collision', message, ...(details === undefined ? {} : { details }) }),
        ),
      );
    }
    if (logs !== undefined) {
      this.#unsubscribe.push(logs((line) => this.log({ ...line, logger: 'robot' })));
    }
    this.#timer = setInterval(() => this.#poll(), this.#pollMs);
    this.#timer.unref?.();
  }

  #stop(): void {
    if (this.#timer !== undefined) clearInterval(this.#timer);
    this.#timer = undefined;
    for (const unsubscribe of this.#unsubscribe.splice(0)) unsubscribe();
  }

  #status(): SafetyStatus | undefined {
    try {
      return this.#hal.safety.getSafetyStatus();
    } catch {
      return undefined;
    }
  }

  #isLow(status: SafetyStatus): boolean {
    return status.batteryLevel < this.#lowPercent;
  }

  #poll(): void {
    const status = this.#status();
    // faults that came with a latch or link change belong to that event, not to one of their own
    const fresh = status === undefined ? [] : status.errors.filter((e) => !this.#errors.has(e));
    const changed = (status !== undefined && this.#latch(status, fresh)) || this.#linkChange(fresh);
    if (status === undefined) return;
    if (!changed)
      for (const error of fresh) this.add({ type: 'fault', message: `Fault: ${error}` });
    this.#errors = new Set(status.errors);
    this.#battery(status);
  }

  /** Adds the event of a changed link; answers whether it changed. */
  #linkChange(faults: string[]): boolean {
    const link = this.#sources.link?.();
    if (link === undefined || link === this.#link) return false;
    const before = this.#link;
    this.#link = link;
    const details = faults.length === 0 ? {} : { details: { faults } };
    if (link === 'lost') {
      this.add({
        type: 'link_lost',
        message: 'The link to the robot is lost; reconnecting',
        ...details,
      });
      return true;
    }
    if (link === 'connected' && before === 'lost') {
      this.add({ type: 'link_back', message: 'The link to the robot is back', ...details });
      return true;
    }
    return false;
  }

  /** Adds the event of a latched or cleared e-stop; answers whether it changed. */
  #latch(status: SafetyStatus, faults: string[]): boolean {
    if (status.emergencyStopped === this.#latched) return false;
    const latched = status.emergencyStopped;
    this.#latched = latched;
    const what = latched ? 'estop' : 'reset';
    const byClient = this.#pending[what] > 0;
    this.#pending = { estop: 0, reset: 0 };
    const by = byClient ? 'mcp-client' : 'elsewhere';
    const who = byClient ? 'by an MCP client' : 'from elsewhere (not through this MCP server)';
    const details = faults.length === 0 ? {} : { details: { faults } };
    if (latched) {
      if (!byClient) this.stopped();
      const reason = status.emergencyStopReason;
      this.add({
        type: 'emergency_stop',
        by,
        ...(reason === undefined ? {} : { reason }),
        message: `Emergency stop ${who}${reason === undefined ? '' : `: ${reason}`}`,
        ...details,
      });
    } else {
      this.add({ type: 'reset', by, message: `Emergency stop reset ${who}`, ...details });
    }
    return true;
  }

  #battery(status: SafetyStatus): void {
    const low = this.#isLow(status);
    if (low && !this.#low) {
      this.add({
        type: 'low_battery',
        message: `Battery low: ${Math.round(status.batteryLevel)} %`,
        details: {
          batteryLevel: status.batteryLevel,
          ...(status.batteryVoltage === undefined ? {} : { batteryVoltage: status.batteryVoltage }),
        },
      });
    }
    this.#low = low;
  }

  #guardEvent(event: GuardEventLike): void {
    if (event.type === 'obstacle') {
      const stop = event.stop ?? {};
      this.add({
        type: 'guard_stop',
        message:
          `The guard ${stop.when === 'before' ? 'refused a motion' : 'stopped the robot'}: ` +
          `something ${stop.distanceM ?? '?'} m ahead` +
          (stop.source === undefined ? '' : ` (${stop.source})`),
        details: { ...stop },
      });
    } else if (event.message !== undefined) {
      this.log({ level: 'warn', logger: 'guard', message: event.message });
    }
  }
}

const feeds = new WeakMap<HardwareAbstractionLayer, RobotEvents>();

/**
 * The one feed of `hal`, made with `sources` the first time it is asked for: every server of one
 * robot shares it (its events, and a stop in one session withdrawing the questions of all).
 */
export function eventsOf(
  hal: HardwareAbstractionLayer,
  sources: RobotEventSources = {},
): RobotEvents {
  let feed = feeds.get(hal);
  if (feed === undefined) {
    feed = new RobotEvents(hal, sources);
    feeds.set(hal, feed);
  }
  return feed;
}
