import { argsFromObject, HAL_CALL_TABLE, HalError, invokeSpec } from '@hal/types';
import type { CallTable, HardwareAbstractionLayer } from '@hal/types';

/**
 * Runs one HAL call of `table` with validated named arguments, passed in the call's order;
 * answers its HALToolResult or value (a boolean or nothing as the tool presents it).
 */
export async function dispatch(
  hal: HardwareAbstractionLayer,
  call: string,
  args: Readonly<Record<string, unknown>>,
  table: CallTable = HAL_CALL_TABLE,
): Promise<unknown> {
  const spec = table.find((entry) => entry.name === call);
  if (spec === undefined) throw new HalError('INVALID_PARAMETER', `unknown HAL call "${call}"`);
  const value = await invokeSpec(hal, spec, argsFromObject(spec, args));
  return spec.tool.answer === undefined ? value : spec.tool.answer(value);
}
