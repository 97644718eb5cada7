// The served HAL with a tap on what the view shows of others' calls: log lines, e-stops and
// resets, captured frames. Everything else passes through untouched; a call answers exactly as
// the HAL answers it, and what the view does with it never throws into the caller.
import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';

/** What the tap tells the view. */
export interface TapListener {
  log(message: unknown, level: unknown): void;
  safety(
    event: 'emergency_stop' | 'reset',
    result: HALToolResult | undefined,
    reason?: string,
  ): void;
  frame(dataUrl: string): void;
}

function quietly(run: () => void): void {
  try {
    run();
  } catch {
    // the view's trouble is never the caller's
  }
}

/** A proxy of `target` whose `wrap[name]` replaces its method of that name, bound to it. */
function withMethods<T extends object>(
  target: T,
  wrap: Record<
    string,
    (original: (...args: unknown[]) => unknown) => (...args: unknown[]) => unknown
  >,
): T {
  return new Proxy(target, {
    get(t, key) {
      const value: unknown = Reflect.get(t, key, t);
      if (typeof value !== 'function') return value;
      const bound = (value as (...args: unknown[]) => unknown).bind(t);
      const make = typeof key === 'string' ? wrap[key] : undefined;
      return make === undefined ? bound : make(bound);
    },
  });
}

/** `hal` with the tap; `listener` hears each tapped call as it answers. */
export function tapHal(
  hal: HardwareAbstractionLayer,
  listener: TapListener,
): HardwareAbstractionLayer {
  const communication = withMethods(hal.communication, {
    log:
      (original) =>
      (message, level, ...rest) => {
        const out = original(message, level, ...rest);
        quietly(() => listener.log(message, level));
        return out;
      },
  });
  const safetyCall =
    (event: 'emergency_stop' | 'reset') =>
    (original: (...args: unknown[]) => unknown) =>
    (...args: unknown[]) => {
      const out = original(...args) as Promise<HALToolResult>;
      const reason = typeof args[0] === 'string' ? args[0] : undefined;
      void Promise.resolve(out).then(
        (result) => quietly(() => listener.safety(event, result, reason)),
        () => quietly(() => listener.safety(event, undefined, reason)),
      );
      return out;
    };
  const safety = withMethods(hal.safety, {
    emergencyStop: safetyCall('emergency_stop'),
    resetEmergencyStop: safetyCall('reset'),
  });
  const vision = withMethods(hal.vision, {
    captureFrame: (original) => () => {
      const out = original() as Promise<string>;
      void Promise.resolve(out).then(
        (frame) => quietly(() => listener.frame(frame)),
        () => undefined,
      );
      return out;
    },
  });
  const replaced = new Map<string | symbol, unknown>([
    ['communication', communication],
    ['safety', safety],
    ['vision', vision],
  ]);
  return new Proxy(hal, {
    get(target, key) {
      if (replaced.has(key)) return replaced.get(key);
      const value: unknown = Reflect.get(target, key, target);
      return typeof value === 'function'
        ? (value as (...args: unknown[]) => unknown).bind(target)
        : value;
    },
  });
}
