import { isPromiseLike } from './call-values.js';

/** A call made through an intercepted object. */
export interface InterceptedCall {
  /** The subsystem (`locomotion`), or undefined for a method of the object itself. */
  subsystem: string | undefined;
  method: string;
  args: unknown[];
}

/** How an intercepted call ended. */
export type CallOutcome = 'returned' | 'threw' | 'resolved' | 'rejected';

/** What {@link interceptCalls} tells of each call. `S` is what `started` hands to `answered`. */
export interface CallHooks<S> {
  /** The call is about to run. */
  started(call: InterceptedCall): S;
  /** The call answered (its value, or what it threw or rejected with), before its caller has it. */
  answered(call: InterceptedCall, started: S, outcome: CallOutcome, value: unknown): void;
}

/**
 * `target` with every method, and every method of the subsystems named, seen by `hooks`; it
 * otherwise behaves as `target`: the same results, the same errors, synchronous calls still
 * synchronous. Methods are found as they are read, not listed, so a method added to the object
 * is seen with no change here.
 *
 * The object handed back is a plain object in front of a Proxy of the real one. The first read
 * of a method (or a subsystem) goes through the Proxy, which puts the wrapped one on the front
 * object as a read-only property, so every later read is a plain property read: a Proxy trap,
 * or an accessor, on every call cost a paced loop's call microseconds. A wrapped method calls
 * the real object's current function of its name, and a wrapped subsystem reads through to the
 * object's current subsystem, so a method or subsystem replaced on the real object is seen as
 * replaced. Assigning a method or a subsystem through the wrapper is a TypeError (replace it on
 * the real object); everything else (fields, getters, `in`, `instanceof`, other assignments)
 * goes through the Proxy to the real object, with it as receiver: getters and #private fields
 * need it.
 */
export function interceptCalls<O extends object, S>(
  target: O,
  subsystems: readonly string[],
  hooks: CallHooks<S>,
): O {
  return front(target, () => target, undefined, subsystems, hooks);
}

function front<O extends object, S>(
  target: O,
  current: () => object,
  subsystem: string | undefined,
  subsystems: readonly string[],
  hooks: CallHooks<S>,
): O {
  const out: Record<PropertyKey, unknown> = {};
  const keep = <V>(prop: string, value: V): V => {
    Object.defineProperty(out, prop, { value, writable: false, configurable: true });
    return value;
  };
  const isSubsystem = (prop: PropertyKey): prop is string =>
    subsystem === undefined && typeof prop === 'string' && subsystems.includes(prop);
  const proxy = new Proxy(target, {
    get(_target, prop) {
      const obj = current();
      const value: unknown = Reflect.get(obj, prop, obj);
      if (typeof prop !== 'string' || prop === 'constructor') return value;
      if (isSubsystem(prop)) {
        if (typeof value !== 'object' || value === null) return value;
        const sub = (): object => {
          const now: unknown = (current() as Record<string, unknown>)[prop];
          return typeof now === 'object' && now !== null ? now : value;
        };
        return keep(prop, front(value, sub, prop, subsystems, hooks));
      }
      if (typeof value !== 'function') return value;
      return keep(prop, method(current, subsystem, prop, hooks));
    },
    set(_target, prop, value: unknown) {
      const obj = current();
      if (
        isSubsystem(prop) ||
        typeof value === 'function' ||
        typeof Reflect.get(obj, prop, obj) === 'function'
      ) {
        throw new TypeError(
          `cannot assign ${String(prop)} through a recorded HAL: assign it on the HAL itself`,
        );
      }
      return Reflect.set(obj, prop, value, obj);
    },
  });
  Object.setPrototypeOf(out, proxy);
  return out as O;
}

function method<S>(
  owner: () => object,
  subsystem: string | undefined,
  name: string,
  hooks: CallHooks<S>,
) {
  const label = subsystem === undefined ? name : `${subsystem}.${name}`;
  return function intercepted(...args: unknown[]): unknown {
    const self = owner();
    const fn: unknown = (self as Record<string, unknown>)[name];
    if (typeof fn !== 'function') throw new TypeError(`${label} is not a function`);
    const call: InterceptedCall = { subsystem, method: name, args };
    const started = hooks.started(call);
    let out: unknown;
    try {
      out = (fn as (...a: unknown[]) => unknown).apply(self, args);
    } catch (error) {
      hooks.answered(call, started, 'threw', error);
      throw error;
    }
    if (!isPromiseLike(out)) {
      hooks.answered(call, started, 'returned', out);
      return out;
    }
    return Promise.resolve(out).then(
      (value) => {
        hooks.answered(call, started, 'resolved', value);
        return value;
      },
      (error: unknown) => {
        hooks.answered(call, started, 'rejected', error);
        throw error;
      },
    );
  };
}
