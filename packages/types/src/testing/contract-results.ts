import { describe, expect, it } from 'vitest';
import { isHalError } from '../errors.js';
import { HALToolResultSchema } from '../result.js';
import type { HALToolResult } from '../result.js';
import { HAL_CALL_TABLE } from '../schemas/call-table.js';
import type { CallName } from '../schemas/calls.js';
import { invokeCall } from '../schemas/invoke-call.js';
import type { ContractContext } from './contract-expect.js';

/**
 * Valid arguments for every call, in the order the suite makes them: motions, commands, reads,
 * then the e-stop, the reads while it is latched, and its reset. A call added to the table needs
 * its sample here (the type says so), and so is checked on every HAL.
 */
const SAMPLES: ReadonlyArray<readonly [CallName, readonly unknown[]]> = [
  ['moveForward', [2]],
  ['moveBackward', [2]],
  ['rotate', ['left', 10]],
  ['moveTo', [0.01, 0, 0]],
  ['drive', [60, 60, 100]],
  ['stop', []],
  ['setLED', [10, 20, 30, 'blink']],
  ['speak', ['hello']],
  ['playSound', ['beep']],
  ['log', ['the result contract', 'info']],
  ['getPose', []],
  ['captureFrame', []],
  ['scan', ['quick']],
  ['getDistanceSensors', []],
  ['getLineSensors', []],
  ['getIMU', []],
  ['emergencyStop', ['result contract']],
  ['isEmergencyStopped', []],
  ['getSafetyStatus', []],
  ['resetEmergencyStop', []],
];

/** The calls every HAL answers with success (the others may fail NOT_IMPLEMENTED instead). */
const ALWAYS: ReadonlySet<CallName> = new Set<CallName>([
  'moveForward',
  'moveBackward',
  'rotate',
  'moveTo',
  'drive',
  'stop',
  'log',
  'getPose',
  'getIMU',
  'emergencyStop',
  'isEmergencyStopped',
  'getSafetyStatus',
  'resetEmergencyStop',
]);

function isResult(value: unknown): value is HALToolResult {
  return HALToolResultSchema.safeParse(value).success;
}

/**
 * Every call's answer matches the call table: the `data` of a successful result, or the value of
 * a value call, parses with the table's schema for that call, so the two worlds answer alike
 * (the same field names, the same types).
 */
export function describeResultContract(ctx: ContractContext): void {
  const { timeout } = ctx;

  describe('results match the call table', () => {
    it('has a sample for every call of the table', () => {
      expect(SAMPLES.map(([name]) => name).sort()).toEqual(
        HAL_CALL_TABLE.map((spec) => spec.name).sort(),
      );
    });

    it(
      "answers every call with data of the table's schema (or NOT_IMPLEMENTED where it may)",
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const mismatches: string[] = [];
        const answers = new Map<CallName, unknown>();
        for (const [name, args] of SAMPLES) {
          const spec = HAL_CALL_TABLE.find((entry) => entry.name === name);
          if (spec === undefined) continue; // the first test reports it
          let answer: unknown;
          try {
            answer = await invokeCall(hal, name, args);
          } catch (error) {
            const code = isHalError(error) ? error.code : String(error);
            if (ALWAYS.has(name) || code !== 'NOT_IMPLEMENTED') {
              mismatches.push(`${name}: rejected ${code}`);
            }
            continue;
          }
          let data: unknown = answer;
          if (spec.kind === 'motion' || spec.kind === 'result') {
            if (!isResult(answer)) {
              mismatches.push(`${name}: not a HALToolResult: ${JSON.stringify(answer)}`);
              continue;
            }
            if (!answer.success) {
              if (ALWAYS.has(name) || answer.code !== 'NOT_IMPLEMENTED') {
                mismatches.push(`${name}: failed ${answer.code ?? ''} ${answer.error ?? ''}`);
              }
              continue;
            }
            data = answer.data ?? {};
          }
          const parsed = spec.data.safeParse(data);
          if (!parsed.success) {
            const issue = parsed.error.issues[0];
            mismatches.push(
              `${name}: ${JSON.stringify(data)} does not match: ${issue?.path.join('.') ?? ''} ${issue?.message ?? ''}`,
            );
          }
          answers.set(name, data);
        }
        expect(mismatches).toEqual([]);
        expect(answers.get('isEmergencyStopped')).toBe(true);
        expect(answers.get('resetEmergencyStop')).toMatchObject({ wasEmergencyStopped: true });
        expect(hal.safety.isEmergencyStopped()).toBe(false);
      },
    );
  });
}
