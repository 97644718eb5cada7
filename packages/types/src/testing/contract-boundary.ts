import { describe, expect, it } from 'vitest';
import type { HalErrorCode } from '../errors.js';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { PoseSchema, SafetyStatusSchema, ScanResultSchema } from '../pose.js';
import type { Pose } from '../pose.js';
import type { HALToolResult } from '../result.js';
import type { CallName, CallSpec } from '../schemas/call-table.js';
import { invokeSpec } from '../schemas/invoke-call.js';
import type { ContractContext } from './contract-expect.js';
import { expectFailedResult, expectRejected, expectSucceeded, settle } from './contract-expect.js';
import { sampledCalls } from './contract-samples.js';

type Hal = HardwareAbstractionLayer;
/** A bad call: what it is, the call, the code it must fail with, the parameter it must name. */
type BadCall = [string, (h: Hal) => Promise<HALToolResult>, HalErrorCode, string];

// Casts that let a test pass what a JavaScript caller (or an LLM's JSON) might pass.
const str = (value: string) => value as unknown as number;
const num = (value: number) => value as unknown as string;
const none = undefined as unknown as number;
const { NaN: nan, POSITIVE_INFINITY: inf, NEGATIVE_INFINITY: minusInf } = Number;

/** Bad arguments for every call that takes any, grouped by call (see {@link boundaryCoverage}). */
const BAD_CALLS: Partial<Record<CallName, BadCall[]>> = {
  drive: [
    ['Infinity right power', (h) => h.locomotion.drive(0, inf), 'INVALID_PARAMETER', 'right'],
    ['a string power', (h) => h.locomotion.drive(str('100'), 0), 'INVALID_PARAMETER', 'left'],
    ['no right power', (h) => h.locomotion.drive(100, none), 'INVALID_PARAMETER', 'right'],
    ['a NaN duration', (h) => h.locomotion.drive(100, 100, nan), 'INVALID_PARAMETER', 'durationMs'],
    ['a power under -255', (h) => h.locomotion.drive(-256, 0), 'RANGE_EXCEEDED', 'left'],
  ],
  moveTo: [
    ['an infinite y', (h) => h.locomotion.moveTo(0.1, inf, 0), 'INVALID_PARAMETER', 'y'],
    ['a string z', (h) => h.locomotion.moveTo(0.1, 0, str('0')), 'INVALID_PARAMETER', 'z'],
    ['no y', (h) => h.locomotion.moveTo(0.1, none, 0), 'INVALID_PARAMETER', 'y'],
    ['a NaN speed', (h) => h.locomotion.moveTo(0.1, 0, 0, nan), 'INVALID_PARAMETER', 'speed'],
    ['a zero speed', (h) => h.locomotion.moveTo(0.1, 0, 0, 0), 'RANGE_EXCEEDED', 'speed'],
    ['a negative speed', (h) => h.locomotion.moveTo(0.1, 0, 0, -0.01), 'RANGE_EXCEEDED', 'speed'],
    ['a point far away', (h) => h.locomotion.moveTo(1e6, 0, 0), 'RANGE_EXCEEDED', 'x'],
  ],
  rotate: [
    [
      'no direction',
      (h) => h.locomotion.rotate(num(none) as 'left', 90),
      'INVALID_PARAMETER',
      'direction',
    ],
    ['infinite degrees', (h) => h.locomotion.rotate('right', inf), 'INVALID_PARAMETER', 'degrees'],
    [
      'a string angle',
      (h) => h.locomotion.rotate('left', str('90')),
      'INVALID_PARAMETER',
      'degrees',
    ],
    ['zero degrees', (h) => h.locomotion.rotate('left', 0), 'RANGE_EXCEEDED', 'degrees'],
    ['a million degrees', (h) => h.locomotion.rotate('left', 1e6), 'RANGE_EXCEEDED', 'degrees'],
  ],
  moveForward: [
    ['NaN cm', (h) => h.locomotion.moveForward(nan), 'INVALID_PARAMETER', 'distanceCm'],
    ['no distance', (h) => h.locomotion.moveForward(none), 'INVALID_PARAMETER', 'distanceCm'],
    ['-Infinity cm', (h) => h.locomotion.moveForward(minusInf), 'INVALID_PARAMETER', 'distanceCm'],
    ['0 cm', (h) => h.locomotion.moveForward(0), 'RANGE_EXCEEDED', 'distanceCm'],
  ],
  moveBackward: [
    ['NaN cm', (h) => h.locomotion.moveBackward(nan), 'INVALID_PARAMETER', 'distanceCm'],
    ['Infinity cm', (h) => h.locomotion.moveBackward(inf), 'INVALID_PARAMETER', 'distanceCm'],
    ['a negative distance', (h) => h.locomotion.moveBackward(-1), 'RANGE_EXCEEDED', 'distanceCm'],
    ['1e6 cm', (h) => h.locomotion.moveBackward(1e6), 'RANGE_EXCEEDED', 'distanceCm'],
  ],
  speak: [
    ['a number', (h) => h.communication.speak(num(42)), 'INVALID_PARAMETER', 'text'],
    ['nothing', (h) => h.communication.speak(num(none)), 'INVALID_PARAMETER', 'text'],
    ['an empty text', (h) => h.communication.speak(''), 'INVALID_PARAMETER', 'text'],
    [
      'an unknown urgency',
      (h) => h.communication.speak('hi', 'shout' as 'info'),
      'INVALID_PARAMETER',
      'urgency',
    ],
  ],
  setLED: [
    ['a NaN green', (h) => h.communication.setLED(0, nan, 0), 'INVALID_PARAMETER', 'g'],
    ['a fractional blue', (h) => h.communication.setLED(0, 0, 1.5), 'INVALID_PARAMETER', 'b'],
    ['a negative red', (h) => h.communication.setLED(-1, 0, 0), 'RANGE_EXCEEDED', 'r'],
    ['no blue', (h) => h.communication.setLED(0, 0, none), 'INVALID_PARAMETER', 'b'],
    [
      'an unknown pattern',
      (h) => h.communication.setLED(0, 0, 0, 'strobe' as 'solid'),
      'INVALID_PARAMETER',
      'pattern',
    ],
  ],
  playSound: [
    ['a number', (h) => h.communication.playSound(num(7)), 'INVALID_PARAMETER', 'soundId'],
    ['an empty id', (h) => h.communication.playSound(''), 'INVALID_PARAMETER', 'soundId'],
  ],
};

/**
 * The calls that take arguments but are not in {@link BAD_CALLS}, and why: each is refused (or
 * not) by a rule of its own, checked where this says.
 */
const CHECKED_ELSEWHERE: Partial<Record<CallName, string>> = {
  emergencyStop:
    'never refused for its argument: the e-stop group gives it awkward reasons and checks each is stored sanitized',
  scan: 'a value call: the test "rejects scan with an unknown mode" below',
  log: 'never throws: the test "never throws from log" below gives it bad messages and levels',
};

/**
 * How the boundary group exercises `spec`: `bad arguments` when it gives the call bad arguments,
 * else why not (the call takes none, or another test checks its rule); undefined when the suite
 * misses the call, which the suite's completeness test reports.
 */
export function boundaryCoverage(spec: CallSpec): string | undefined {
  if (BAD_CALLS[spec.name as CallName] !== undefined) return 'bad arguments';
  if (spec.params.length === 0) return 'takes no arguments';
  return CHECKED_ELSEWHERE[spec.name as CallName];
}

/**
 * The boundary's rules, as any HAL must show them: every bad argument to every call is refused
 * with the right code before anything moves; value-returning calls reject with a HalError;
 * `log` never throws; state reads are well formed.
 */
export function describeBoundaryContract(ctx: ContractContext): void {
  const { timeout } = ctx;
  const pose = async (): Promise<Pose> => PoseSchema.parse(await ctx.hal().locomotion.getPose());

  describe('one boundary for every call', () => {
    for (const [call, cases = []] of Object.entries(BAD_CALLS)) {
      it(
        `refuses every bad argument to ${call} with its code, naming the parameter, and nothing moves`,
        { timeout },
        async () => {
          const hal = await ctx.ready();
          const before = await pose();
          for (const [title, run, code, parameter] of cases) {
            expectFailedResult(await run(hal), code, parameter, `${call} with ${title}:`);
          }
          const after = await pose();
          expect(after.position).toEqual(before.position);
          expect(after.rotation.yaw).toBe(before.rotation.yaw);
          expectSucceeded(await hal.locomotion.stop(), 'stop after the refusals:');
        },
      );
    }

    it(
      'refuses a moveTo slower than the robot allows with RANGE_EXCEEDED quoting the minimum',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const result = await hal.locomotion.moveTo(0.05, 0, 0, 1e-9);
        expectFailedResult(result, 'RANGE_EXCEEDED', 'speed');
        expect(result.error).toMatch(/"speed" must be at least \d/);
        expect(result.details).toMatchObject({ parameter: 'speed', bound: 'min' });
        expect((await pose()).position.x).toBe(0);
      },
    );

    it(
      'rejects scan with an unknown mode with INVALID_PARAMETER, whatever sensors it has',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        expectRejected(
          await settle(() => hal.vision.scan('bogus' as 'quick')),
          'INVALID_PARAMETER',
          'mode',
          "scan('bogus'):",
        );
        expectRejected(
          await settle(() => hal.vision.scan(3 as unknown as 'quick')),
          'INVALID_PARAMETER',
          'mode',
          'scan(3):',
        );
      },
    );

    it('never throws from log, whatever it is given, and keeps working', { timeout }, async () => {
      const hal = await ctx.ready();
      const log = hal.communication.log.bind(hal.communication);
      expect(() => log('fine', 'info')).not.toThrow();
      expect(() => log('x', 'bogus' as 'info')).not.toThrow();
      expect(() => log(42 as unknown as string)).not.toThrow();
      expect(() => log(undefined as unknown as string, 'warn')).not.toThrow();
      expect(() => log({ toString: null } as unknown as string)).not.toThrow();
      expect(() => log('x'.repeat(100_000), 'error')).not.toThrow();
      expect(() => log('still here', 'debug')).not.toThrow();
      expectSucceeded(await hal.locomotion.stop());
    });

    it('answers every read with a well-formed value or a HalError', { timeout }, async () => {
      const hal = await ctx.ready();
      // every read of the table with its sample, and scan's full mode
      const reads: Array<[string, () => Promise<unknown>, { parse(v: unknown): unknown }]> = [
        ...sampledCalls((spec) => spec.kind === 'value' && !spec.cached).map(
          ([spec, args]) =>
            [spec.name, () => invokeSpec(hal, spec, args), spec.data] as [
              string,
              () => Promise<unknown>,
              { parse(v: unknown): unknown },
            ],
        ),
        ['scan full', () => hal.vision.scan('full'), ScanResultSchema],
      ];
      for (const [name, read, schema] of reads) {
        const outcome = await settle(read);
        if ('value' in outcome) {
          expect(() => schema.parse(outcome.value), name).not.toThrow();
        } else {
          expectRejected(outcome, 'NOT_IMPLEMENTED', undefined, `${name}:`);
        }
      }
      const status = SafetyStatusSchema.parse(hal.safety.getSafetyStatus());
      expect(status.emergencyStopped).toBe(hal.safety.isEmergencyStopped());
      expect(hal.safety.isEmergencyStopped()).toBe(false);
    });
  });
}
