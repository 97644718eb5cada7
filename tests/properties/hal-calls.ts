import { fc } from '@fast-check/vitest';
import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';

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

/** One public call: its name, whether it moves the robot, and how to invoke it. */
export interface HalCall {
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

// The HAL methods are called with any arguments on purpose: that is what is under test.
type AnyFn = (...args: unknown[]) => unknown;
const call = (fn: unknown, self: unknown, args: unknown[]) => (fn as AnyFn).apply(self, args);

/** Picks which of several argument positions is broken, the others being valid. */
function oneBroken(valid: fc.Arbitrary<unknown>[], broken: fc.Arbitrary<unknown>[]) {
  return fc
    .nat({ max: valid.length - 1 })
    .chain((i) => fc.tuple(...valid.map((v, k) => (k === i ? (broken[k] ?? v) : v))));
}

/** A required parameter: broken, or missing. */
const orMissing = (broken: fc.Arbitrary<unknown>) => fc.oneof(broken, fc.constant(undefined));

const power = inside(-255, 255);
const badPower = orMissing(outside(-255, 255));
const badCm = orMissing(outside(0, 1e6));
const degrees = inside(0, 360);
const badDegrees = orMissing(outside(0, 1e7));
const metres = inside(-1, 1);
const badMetres = orMissing(outside(-1e7, 1e7, 1e15));
const badColour = orMissing(outside(0, 255));
const anyArg = fc.oneof(notANumber, fc.double(), fc.integer({ min: -300, max: 300 }));

export const HAL_CALLS: HalCall[] = [
  {
    name: 'locomotion.drive',
    motion: true,
    returnsResult: true,
    invalid: oneBroken(
      [power, power, inside(0, 5000)],
      [badPower, badPower, outside(0, 1e9, 1e15)],
    ),
    any: fc.array(anyArg, { maxLength: 3 }),
    run: (hal, a) => call(hal.locomotion.drive, hal.locomotion, a),
  },
  {
    name: 'locomotion.moveTo',
    motion: true,
    returnsResult: true,
    invalid: oneBroken(
      [metres, metres, fc.constant(0), inside(0, 0.04)],
      [badMetres, badMetres, notANumber, outside(0, 1e3)],
    ),
    any: fc.array(anyArg, { maxLength: 4 }),
    run: (hal, a) => call(hal.locomotion.moveTo, hal.locomotion, a),
  },
  {
    name: 'locomotion.rotate',
    motion: true,
    returnsResult: true,
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
    run: (hal, a) => call(hal.locomotion.rotate, hal.locomotion, a),
  },
  {
    name: 'locomotion.moveForward',
    motion: true,
    returnsResult: true,
    invalid: fc.tuple(badCm),
    any: fc.tuple(anyArg),
    run: (hal, a) => call(hal.locomotion.moveForward, hal.locomotion, a),
  },
  {
    name: 'locomotion.moveBackward',
    motion: true,
    returnsResult: true,
    invalid: fc.tuple(badCm),
    any: fc.tuple(anyArg),
    run: (hal, a) => call(hal.locomotion.moveBackward, hal.locomotion, a),
  },
  {
    name: 'communication.setLED',
    motion: false,
    returnsResult: true,
    invalid: oneBroken(
      [
        fc.integer({ min: 0, max: 255 }),
        fc.integer({ min: 0, max: 255 }),
        fc.integer({ min: 0, max: 255 }),
      ],
      [badColour, badColour, badColour],
    ),
    any: fc.array(anyArg, { maxLength: 4 }),
    run: (hal, a) => call(hal.communication.setLED, hal.communication, a),
  },
  {
    name: 'communication.speak',
    motion: false,
    returnsResult: true,
    any: fc.tuple(fc.oneof(fc.string({ maxLength: 600 }), anyArg), fc.option(fc.string())),
    run: (hal, a) => call(hal.communication.speak, hal.communication, a),
  },
  {
    name: 'communication.playSound',
    motion: false,
    returnsResult: true,
    any: fc.tuple(fc.oneof(fc.string({ maxLength: 120 }), anyArg)),
    run: (hal, a) => call(hal.communication.playSound, hal.communication, a),
  },
  {
    name: 'locomotion.stop',
    motion: false,
    returnsResult: true,
    any: fc.array(anyArg, { maxLength: 2 }),
    run: (hal, a) => call(hal.locomotion.stop, hal.locomotion, a),
  },
  {
    name: 'locomotion.getPose',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.locomotion.getPose(),
  },
  {
    name: 'vision.getDistanceSensors',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.vision.getDistanceSensors(),
  },
  {
    name: 'vision.scan',
    motion: false,
    returnsResult: false,
    any: fc.array(fc.oneof(fc.constantFrom('full', 'targeted', 'quick'), anyArg), { maxLength: 1 }),
    run: (hal, a) => call(hal.vision.scan, hal.vision, a),
  },
  {
    name: 'vision.captureFrame',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.vision.captureFrame(),
  },
  {
    name: 'vision.getLineSensors',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.vision.getLineSensors(),
  },
  {
    name: 'vision.getIMU',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.vision.getIMU(),
  },
  {
    name: 'safety.getSafetyStatus',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.safety.getSafetyStatus(),
  },
  {
    name: 'safety.isEmergencyStopped',
    motion: false,
    returnsResult: false,
    any: fc.constant([]),
    run: (hal) => hal.safety.isEmergencyStopped(),
  },
  {
    name: 'communication.log',
    motion: false,
    returnsResult: false,
    any: fc.tuple(
      fc.oneof(fc.string({ maxLength: 300 }), anyArg),
      fc.oneof(
        fc.constantFrom('debug', 'info', 'warn', 'error'),
        fc.string({ maxLength: 20 }),
        anyArg,
      ),
    ),
    run: (hal, a) => call(hal.communication.log, hal.communication, a),
  },
];

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
