import type { SimulationHAL } from '@hal/simulation';

/**
 * A SimulationHAL that is always the one `current()` returns: every property read goes to the
 * HAL selected at that moment (methods bound to it). The page's panels hold this one object and
 * so drive whichever robot is selected, with no change of their own.
 */
export function selectedHal(current: () => SimulationHAL): SimulationHAL {
  return new Proxy(current(), {
    get(_first, property) {
      const hal = current();
      const value: unknown = Reflect.get(hal, property, hal);
      return typeof value === 'function'
        ? (value as (...a: unknown[]) => unknown).bind(hal)
        : value;
    },
    set(_first, property, value) {
      return Reflect.set(current(), property, value);
    },
  });
}
