// Runs one decoded call on the served HAL. Arguments are passed positionally, exactly as a local
// caller would pass them, so the HAL's own boundary validates them (and names the parameter).
import { HAL_CALL_TABLE, invokeSpec } from '@hal/types';
import type { CallSpec, CallTable, HardwareAbstractionLayer } from '@hal/types';

/** The entry of a call the server knows, or undefined. */
export function findRemoteCall(
  name: string,
  table: CallTable = HAL_CALL_TABLE,
): CallSpec | undefined {
  return table.find((spec) => spec.name === name);
}

/** True for a call name the server knows. */
export function isRemoteCall(name: string, table: CallTable = HAL_CALL_TABLE): boolean {
  return findRemoteCall(name, table) !== undefined;
}

/** Runs `spec` on `hal` with `args`; a synchronous throw becomes a rejection; `log` answers null. */
export async function dispatchCall(
  hal: HardwareAbstractionLayer,
  spec: CallSpec,
  args: readonly unknown[],
): Promise<unknown> {
  const value = await invokeSpec(hal, spec, args);
  return spec.kind === 'void' ? null : value;
}
