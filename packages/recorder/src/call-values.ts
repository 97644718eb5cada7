// What recordHal reads of a call's arguments, results and errors, and its option checks.
import { HalError, errorMessage } from '@hal/types';

export function isPromiseLike(value: unknown): value is PromiseLike<unknown> {
  return (
    typeof value === 'object' &&
    value !== null &&
    typeof (value as { then?: unknown }).then === 'function'
  );
}

/** The arguments as given, less trailing `undefined`s (an omitted optional argument). */
export function withoutTrailingUndefined(args: readonly unknown[]): unknown[] {
  let end = args.length;
  while (end > 0 && args[end - 1] === undefined) end -= 1;
  return args.slice(0, end);
}

/** A HALToolResult, as motion, stop, e-stop and the other action calls answer. */
export function isToolResult(value: unknown): boolean {
  return (
    typeof value === 'object' &&
    value !== null &&
    typeof (value as { success?: unknown }).success === 'boolean' &&
    typeof (value as { mode?: unknown }).mode === 'string'
  );
}

export function failureOf(value: unknown): { success: boolean; code?: string; error?: string } {
  if (typeof value === 'object' && value !== null && 'success' in value) {
    const result = value as { success: unknown; code?: unknown; error?: unknown };
    if (result.success === false) {
      return {
        success: false,
        ...(typeof result.code === 'string' ? { code: result.code } : {}),
        ...(typeof result.error === 'string' ? { error: result.error } : {}),
      };
    }
  }
  return { success: true };
}

export function errorOf(error: unknown): { code?: string; error: string } {
  const code = (error as { code?: unknown } | null)?.code;
  return {
    ...(typeof code === 'string' ? { code } : {}),
    error: errorMessage(error),
  };
}

/** A sampling period: a finite number of ms >= 0, else INVALID_PARAMETER naming the option. */
export function period(name: string, ms: number): number {
  if (typeof ms !== 'number' || !Number.isFinite(ms) || ms < 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${name}" must be a finite number of ms >= 0, got ${String(ms)}`,
      {
        details: { parameter: name },
      },
    );
  }
  return ms;
}
