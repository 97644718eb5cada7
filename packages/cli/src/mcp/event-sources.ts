// Where `hal mcp` reads the robot's events from besides its safety status: the guard's stops and
// warnings, the simulator's collisions, a robot link's state, and the HAL's log lines (the calls
// of `communication.log` the tools make, tapped on their way to the robot).
import type { RobotEventSources } from '@hal/mcp';
import type { GuardedHAL } from '@hal/perception';
import { SimulationHAL } from '@hal/simulation';
import type { CommunicationInterface, HardwareAbstractionLayer, LogLevel } from '@hal/types';

type LogListener = (line: { level: LogLevel; message: string }) => void;

/**
 * `hal` with its `communication.log` tapped: every line logged through it also goes to the
 * listeners of `logs`. Everything else is `hal` itself.
 */
export function tapLog(hal: HardwareAbstractionLayer): {
  hal: HardwareAbstractionLayer;
  logs: NonNullable<RobotEventSources['logs']>;
} {
  const listeners = new Set<LogListener>();
  const inner = hal.communication;
  const communication: CommunicationInterface = {
    speak: (text, urgency) => inner.speak(text, urgency),
    setLED: (r, g, b, pattern) => inner.setLED(r, g, b, pattern),
    playSound: (id) => inner.playSound(id),
    log: (message, level) => {
      inner.log(message, level);
      for (const listener of listeners) listener({ level: level ?? 'info', message });
    },
  };
  const tapped = new Proxy(hal, {
    get(target, property) {
      if (property === 'communication') return communication;
      const value: unknown = Reflect.get(target, property, target);
      // methods run on the HAL itself (its private fields are its own)
      return typeof value === 'function' ? (value as () => unknown).bind(target) : value;
    },
  });
  return {
    hal: tapped,
    logs: (listener) => {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

/** The event sources of `robot` (the HAL as opened) with its `guard`, and `logs`. */
export function mcpEventSources(
  robot: HardwareAbstractionLayer,
  guard: GuardedHAL | undefined,
  logs: RobotEventSources['logs'],
): RobotEventSources {
  const sources: RobotEventSources = {};
  if (logs !== undefined) sources.logs = logs;
  if (guard !== undefined) sources.guard = { onEvent: (listener) => guard.onEvent(listener) };
  const link = robot as unknown as { linkState?: unknown };
  if (typeof link.linkState === 'string') sources.link = () => String(link.linkState);
  if (robot instanceof SimulationHAL) {
    sources.collisions = (listener) =>
      robot.events.on('motionFinished', (report) => {
        if (report.outcome !== 'collision' || report.contact === undefined) return;
        const { point, role } = report.contact;
        listener(
          `The robot touched a ${role} at (${point.x.toFixed(3)}, ${point.y.toFixed(3)}) m and stopped`,
          { contact: report.contact },
        );
      });
  }
  return sources;
}
