import { fc } from '@fast-check/vitest';
import { callMethod, HAL_CALL_TABLE } from '@hal/types';
import type { CallName, HALToolResult, HardwareAbstractionLayer } from '@hal/types';

/*
 * Every public HAL call as data, for the property tests: how to make it, and arbitraries for
 * its arguments. `invalid` arguments break at least one documented limit or type, so the HAL
 * must refuse the call; out-of-range numbers are far beyond any configured limit.
 */

/** A value given for a parameter that is not a finite number: NaN, infinities, another type. */
const notANumberGiven = fc.oneof(
  fc.constantFrom(Number.NaN, Infinity, -Infinity, null, true, '12', ''),
  fc.string({ maxLength: 8 }),
  fc.object({ maxDepth: 1 }),
  fc.array(fc.integer(), { maxLength: 3 }),
);
/** As above, or missing (for a required parameter). */
const notANumber = fc.oneof(notANumberGiven, fc.constant(undefined));
/**
 * A value given for a number parameter that is not finite or lies outside [min, max]; `far`
 * bounds the outside values. Never undefined: an optional parameter left out is valid.
 */
const outside = (min: number, max: number, far = 1e12) =>
  fc.oneof(
    notANumberGiven,
    // the filters drop -0 next to a bound of 0: fast-check orders -0 below 0, JavaScript does not
    fc.double({ min: -far, max: min, noNaN: true, maxExcluded: true }).filter((v) => v < min),
    fc.double({ min: max, max: far, noNaN: true, minExcluded: true }).filter((v) => v > max),
  );
const inside = (min: number, max: number) =>
  fc.double({ min, max, noNaN: true, minExcluded: true, maxExcluded: true });

/** Picks which of several argument positions is broken, the others being valid. */
function oneBroken(valid: fc.Arbitrary<unknown>[], broken: fc.Arbitrary<unknown>[]) {
  return fc
    .nat({ max: valid.length - 1 })
    .chain((i) => fc.tuple(...valid.map((v, k) => (k === i ? (broken[k] ?? v) : v))));
}

/** A required parameter: broken, or missing. */
const orMissing = (broken: fc.Arbitrary<unknown>) => fc.oneof(broken, fc.constant(undefined));

/** One public call: its name, whether it moves the robot, and how to invoke it. */
export interface HalCall {
  /** `subsystem.method`, e.g. `locomotion.drive`. */
  name: string;
  motion: boolean;
  /** Arguments that must be refused (empty for calls without arguments). */
  invalid?: fc.Arbitrary<unknown[]>;
  /** Any arguments at all, valid or not, of plausible shape. */
  any: fc.Arbitrary<unknown[]>;
  /** Calls the HAL method with the arguments; a result call resolves to a HALToolResult. */
  run: (hal: HardwareAbstractionLayer, args: unknown[]) => unknown;
  /** Whether the call resolves to a HALToolResult (otherwise to a value, or a typed rejection). */
  returnsResult: boolean;
}

/** The arbitraries of one call's arguments. */
interface CallArguments {
  invalid?: fc.Arbitrary<unknown[]>;
  any: fc.Arbitrary<unknown[]>;
}

/** A call the random-call properties leave out, and why (another property covers it). */
interface Exempt {
  exempt: string;
}

const power = inside(-255, 255);
const badPower = orMissing(outside(-255, 255));
const badCm = orMissing(outside(0, 1e6));
const degrees = inside(0, 360);
const badDegrees = orMissing(outside(0, 1e7));
const metres = inside(-1, 1);
const badMetres = orMissing(outside(-1e7, 1e7, 1e15));
const badColour = orMissing(outside(0, 255));
const anyArg = fc.oneof(notANumber, fc.double(), fc.integer({ min: -300, max: 300 }));
const noArguments: CallArguments = { any: fc.constant([]) };

/**
 * The arguments of every call of the call table, by call name. The type asks for every call: a
 * call added to the table needs its arbitraries here (or a reason to be left out), and then the
 * properties make it on both HALs.
 */
export const CALL_ARGUMENTS: Readonly<Record<CallName, CallArguments | Exempt>> = {
  drive: {
    invalid: oneBroken(
      [power, power, inside(0, 5000)],
      [badPower, badPower, outside(0, 1e9, 1e15)],
    ),
    any: fc.array(anyArg, { maxLength: 3 }),
  },
  moveTo: {
    invalid: oneBroken(
      [metres, metres, fc.constant(0), inside(0, 0.04)],
      [badMetres, badMetres, notANumber, outside(0, 1e3)],
    ),
    any: fc.array(anyArg, { maxLength: 4 }),
  },
  rotate: {
    invalid: oneBroken(
      [fc.constantFrom('left', 'right'), degrees],
      [
        fc.oneof(
          fc.string().filter((s) => s !== 'left' && s !== 'right'),
          notANumber,
        ),
        badDegrees,
      ],
    ),
    any: fc.tuple(fc.oneof(fc.constantFrom('left', 'right'), anyArg), anyArg),
  },
  moveForward: { invalid: fc.tuple(badCm), any: fc.tuple(anyArg) },
  moveBackward: { invalid: fc.tuple(badCm), any: fc.tuple(anyArg) },
  setLED: {
    invalid: oneBroken(
      [
        fc.integer({ min: 0, max: 255 }),
        fc.integer({ min: 0, max: 255 }),
        fc.integer({ min: 0, max: 255 }),
      ],
      [badColour, badColour, badColour],
    ),
    any: fc.array(anyArg, { maxLength: 4 }),
  },
  speak: {
    any: fc.tuple(fc.oneof(fc.string({ maxLength: 600 }), anyArg), fc.option(fc.string())),
  },
  playSound: { any: fc.tuple(fc.oneof(fc.string({ maxLength: 120 }), anyArg)) },
  stop: { any: fc.array(anyArg, { maxLength: 2 }) },
  emergencyStop: {
    exempt:
      'it latches, and a latched HAL refuses motion before its arguments; the e-stop property ' +
      'gives it any reason and resets it',
  },
  resetEmergencyStop: { any: fc.array(anyArg, { maxLength: 1 }) },
  getPose: noArguments,
  getDistanceSensors: noArguments,
  scan: {
    any: fc.array(fc.oneof(fc.constantFrom('full', 'targeted', 'quick'), anyArg), { maxLength: 1 }),
  },
  captureFrame: noArguments,
  getLineSensors: noArguments,
  getIMU: noArguments,
  getSafetyStatus: noArguments,
  isEmergencyStopped: noArguments,
  log: {
    any: fc.tuple(
      fc.oneof(fc.string({ maxLength: 300 }), anyArg),
      fc.oneof(
        fc.constantFrom('debug', 'info', 'warn', 'error'),
        fc.string({ maxLength: 20 }),
        anyArg,
      ),
    ),
  },
};

/** The arguments of `name`: its arbitraries, its exemption, or undefined for a call left out. */
export function callArguments(name: string): CallArguments | Exempt | undefined {
  return (CALL_ARGUMENTS as Readonly<Record<string, CallArguments | Exempt>>)[name];
}

/** Every call of the call table the properties make, in the table's order. */
export const HAL_CALLS: HalCall[] = HAL_CALL_TABLE.flatMap((spec): HalCall[] => {
  const args = callArguments(spec.name);
  if (args === undefined || 'exempt' in args) return [];
  return [
    {
      name: `${spec.subsystem}.${spec.method}`,
      motion: spec.kind === 'motion',
      returnsResult: spec.kind === 'motion' || spec.kind === 'result',
      ...(args.invalid === undefined ? {} : { invalid: args.invalid }),
      any: args.any,
      // the HAL methods are called with any arguments on purpose: that is what is under test
      run: (hal, a) => callMethod(hal, spec, a),
    },
  ];
});

/** The calls that take arguments which can be invalid. */
export const REFUSABLE_CALLS = HAL_CALLS.filter((c) => c.invalid !== undefined);

/** Whether `value` has the shape of a HALToolResult for `mode`. */
export function isToolResult(value: unknown, mode: string): value is HALToolResult {
  if (value === null || typeof value !== 'object') return false;
  const r = value as Record<string, unknown>;
  return (
    typeof r['success'] === 'boolean' &&
    typeof r['timestamp'] === 'number' &&
    r['mode'] === mode &&
    (r['success'] === true || typeof r['error'] === 'string')
  );
}
