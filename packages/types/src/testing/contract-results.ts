import { describe, expect, it } from 'vitest';
import { isHalError } from '../errors.js';
import { HALToolResultSchema } from '../result.js';
import type { HALToolResult } from '../result.js';
import { CAPABILITIES } from '../capabilities.js';
import type { CallSpec } from '../schemas/call-table.js';
import { invokeSpec } from '../schemas/invoke-call.js';
import type { ContractContext } from './contract-expect.js';
import { CALL_SAMPLES, sampledCalls, tableCallNames } from './contract-samples.js';

/**
 * The order the suite makes the calls in: every call outside the safety subsystem in the table's
 * order, then the e-stop, the cached safety reads while it is latched, and the rest (its reset).
 */
function resultOrder(): ReadonlyArray<readonly [CallSpec, readonly unknown[]]> {
  const rank = (spec: CallSpec): number =>
    spec.subsystem !== 'safety' ? 0 : spec.tool.safety === 'estop' ? 1 : spec.cached ? 2 : 3;
  return [...sampledCalls()].sort(([a], [b]) => rank(a) - rank(b));
}

/**
 * Whether every HAL must answer `spec` with success: the calls that need no capability beyond the
 * wheels every HAL has (the others may fail NOT_IMPLEMENTED instead).
 */
function always(spec: CallSpec): boolean {
  return spec.tool.requires === undefined || spec.tool.requires === CAPABILITIES.differentialDrive;
}

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
      expect(Object.keys(CALL_SAMPLES).sort()).toEqual(tableCallNames());
    });

    it(
      "answers every call with data of the table's schema (or NOT_IMPLEMENTED where it may)",
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const mismatches: string[] = [];
        const answers = new Map<string, unknown>();
        for (const [spec, args] of resultOrder()) {
          const name = spec.name;
          let answer: unknown;
          try {
            answer = await invokeSpec(hal, spec, args);
          } catch (error) {
            const code = isHalError(error) ? error.code : String(error);
            if (always(spec) || code !== 'NOT_IMPLEMENTED') {
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
              if (always(spec) || answer.code !== 'NOT_IMPLEMENTED') {
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
