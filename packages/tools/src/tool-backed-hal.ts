import { HAL_CALL_TABLE, HAL_ERROR_CODES, HalError, objectFromArgs } from '@hal/types';
import type {
  CallSpec,
  CallSubsystem,
  HALToolResult,
  HalErrorCode,
  HardwareAbstractionLayer,
} from '@hal/types';
import type { ToolCall } from './executor.js';
import type { ToolResult } from './result.js';

const CODES = new Set<string>(HAL_ERROR_CODES);

/** A tool's answer as the HALToolResult a motion call resolves with (refusals included). */
function asHalResult(result: ToolResult, mode: HardwareAbstractionLayer['mode']): HALToolResult {
  const s = result.structured ?? {};
  if (typeof s['success'] === 'boolean') return s as unknown as HALToolResult;
  const code = typeof s['code'] === 'string' ? s['code'] : 'HARDWARE_ERROR';
  return {
    success: false,
    error: typeof s['error'] === 'string' ? s['error'] : code,
    // the executor's own codes (LEASH_DISTANCE, BUDGET_EXCEEDED...) are no HalErrorCode: they
    // travel in the details, so a controller can still tell a refusal from a fault
    ...(CODES.has(code) ? { code: code as HalErrorCode } : { details: { code } }),
    timestamp: 0,
    mode,
  };
}

/** A tool's answer as the value a read call resolves with; a refusal rejects as a HalError. */
function asValue<T>(result: ToolResult): T {
  if (!result.isError) return result.structured as T;
  const s = result.structured ?? {};
  // a tool the executor does not offer: the robot, as the agent has it, cannot do this
  const code =
    typeof s['code'] === 'string' && CODES.has(s['code'])
      ? (s['code'] as HalErrorCode)
      : s['code'] === 'UNKNOWN_TOOL'
        ? 'NOT_IMPLEMENTED'
        : 'HARDWARE_ERROR';
  throw new HalError(code, typeof s['error'] === 'string' ? s['error'] : code);
}

/** Whether `spec` stays on the robot itself: a synchronous read, the log, the e-stop (never refused). */
function direct(spec: CallSpec): boolean {
  return spec.cached || spec.kind === 'void' || spec.tool.safety === 'estop';
}
/** The subsystems that have calls in the table; any other (an arm) is the HAL's own, untouched. */
const SUBSYSTEMS: readonly CallSubsystem[] = [...new Set(HAL_CALL_TABLE.map((s) => s.subsystem))];

/**
 * `hal` with every asynchronous call of its call table (motions, the e-stop's reset, reads, the
 * LED and speech) sent through `execute` as the tool of the same call, so a controller that
 * drives a HAL (the navigation bridge, the skills) meets the same leash, faults and budget as a
 * model and its calls are counted and logged the same way. A call the tools do not offer is
 * refused as a tool would be (a motion answers a failed result, a read rejects). State read
 * synchronously (the e-stop, the safety status, readiness, device info), the log, the lifecycle
 * and the e-stop itself stay on `hal`: the budget must never refuse an e-stop.
 */
export function toolBackedHal(
  hal: HardwareAbstractionLayer,
  execute: (call: ToolCall) => Promise<ToolResult>,
): HardwareAbstractionLayer {
  const run = (spec: CallSpec, args: readonly unknown[]) =>
    execute({ name: spec.tool.name, arguments: objectFromArgs(spec, args) });
  const routed = (subsystem: CallSubsystem): object => {
    const target = (hal as unknown as Record<string, object>)[subsystem] ?? {};
    const specs = new Map(
      HAL_CALL_TABLE.filter((s) => s.subsystem === subsystem && !direct(s)).map((s) => [
        s.method,
        s,
      ]),
    );
    return new Proxy(target, {
      get(t, key, receiver) {
        const spec = typeof key === 'string' ? specs.get(key) : undefined;
        if (spec !== undefined) {
          if (spec.kind === 'motion' || spec.kind === 'result')
            return async (...args: unknown[]) => asHalResult(await run(spec, args), hal.mode);
          if (spec.method === 'captureFrame')
            return async () => {
              const result = await run(spec, []);
              asValue(result);
              const image = result.content.find((c) => c.type === 'image');
              return image === undefined ? '' : `data:image/jpeg;base64,${image.data}`;
            };
          return async (...args: unknown[]) => asValue(await run(spec, args));
        }
        const value: unknown = Reflect.get(t, key, receiver);
        return typeof value === 'function'
          ? (value as (...a: unknown[]) => unknown).bind(t)
          : value;
      },
    });
  };
  const subsystems = new Map(SUBSYSTEMS.map((name) => [name as string | symbol, routed(name)]));
  return new Proxy(hal, {
    get(target, key, receiver) {
      const subsystem = subsystems.get(key);
      if (subsystem !== undefined) return subsystem;
      const value: unknown = Reflect.get(target, key, receiver);
      return typeof value === 'function'
        ? (value as (...a: unknown[]) => unknown).bind(target)
        : value;
    },
  });
}
