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
 * otherwise behaves exactly as `target`: the same results, the same errors, synchronous calls
 * still synchronous. Methods are found as they are read, not listed, so a method added to the
 * object is seen with no change here.
 *
 * The object handed back is a plain object in front of a Proxy of the real one. The first read
 * of a method (or a subsystem) goes through the Proxy, which puts an accessor for it on the
 * front object; every later read is that accessor, which the JIT inlines, where a Proxy trap on
 * every call cost a paced loop's call microseconds. The accessor wraps the real object's current
 * function (a method replaced on the real object is seen as replaced); a write goes to the real
 * object. Everything else (fields, getters, `in`, `instanceof`) reads through the Proxy to the
 * real object, with the real object as receiver: getters and #private fields need it.
 */
export function interceptCalls<O extends object, S>(
  target: O,
  subsystems: readonly string[],
  hooks: CallHooks<S>,
): O {
  return front(target, undefined, subsystems, hooks);
}

function front<O extends object, S>(
  target: O,
  subsystem: string | undefined,
  subsystems: readonly string[],
  hooks: CallHooks<S>,
): O {
  const out: Record<PropertyKey, unknown> = {};
  const keep = (prop: string, wrap: (value: unknown) => unknown): unknown => {
    let seen: unknown;
    let wrapper: unknown;
    const current = (): unknown => {
      const value: unknown = Reflect.get(target, prop, target);
      if (value !== seen) {
        seen = value;
        wrapper = wrap(value);
      }
      return wrapper;
    };
    Object.defineProperty(out, prop, {
      configurable: true,
      get: current,
      set: (value: unknown) => Reflect.set(target, prop, value, target),
    });
    return current();
  };
  const proxy = new Proxy(target, {
    get(obj, prop) {
      const value: unknown = Reflect.get(obj, prop, obj);
      if (typeof prop !== 'string' || prop === 'constructor') return value;
      if (subsystem === undefined && subsystems.includes(prop)) {
        if (typeof value !== 'object' || value === null) return value;
        return keep(prop, (sub) =>
          typeof sub === 'object' && sub !== null ? front(sub, prop, subsystems, hooks) : sub,
        );
      }
      if (typeof value !== 'function') return value;
      return keep(prop, (fn) =>
        typeof fn === 'function'
          ? method(fn as (...args: unknown[]) => unknown, obj, subsystem, prop, hooks)
          : fn,
      );
    },
    set: (obj, prop, value: unknown) => Reflect.set(obj, prop, value, obj),
  });
  Object.setPrototypeOf(out, proxy);
  return out as O;
}

function method<S>(
  fn: (...args: unknown[]) => unknown,
  owner: object,
  subsystem: string | undefined,
  name: string,
  hooks: CallHooks<S>,
) {
  return function intercepted(...args: unknown[]): unknown {
    const call: InterceptedCall = { subsystem, method: name, args };
    const started = hooks.started(call);
    let out: unknown;
    try {
      out = fn.apply(owner, args);
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
