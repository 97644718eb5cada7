import type { HardwareAbstractionLayer } from '../interfaces.js';
import { HAL_CALL_TABLE } from '../schemas/call-table.js';
import type { CallName, CallSpec } from '../schemas/call-table.js';
import { invokeSpec } from '../schemas/invoke-call.js';

/**
 * Valid arguments for every call of the table, small enough for any robot. The type asks for
 * every call: a call added to the table needs its sample here, and then every group that runs
 * "every call" (lifecycle, results, e-stop, capabilities) runs it on every HAL.
 */
export const CALL_SAMPLES: Readonly<Record<CallName, readonly unknown[]>> = Object.freeze({
  moveForward: [2],
  moveBackward: [2],
  rotate: ['left', 10],
  moveTo: [0.01, 0, 0],
  drive: [60, 60, 100],
  stop: [],
  emergencyStop: ['contract test'],
  resetEmergencyStop: [],
  getPose: [],
  captureFrame: [],
  getDistanceSensors: [],
  scan: ['quick'],
  getLineSensors: [],
  getIMU: [],
  getSafetyStatus: [],
  isEmergencyStopped: [],
  setLED: [10, 20, 30, 'blink'],
  speak: ['hello'],
  playSound: ['beep'],
  log: ['the contract suite', 'info'],
});

/** The calls of the table, each with its sample arguments (throws for a call without one). */
export function sampledCalls(
  keep: (spec: CallSpec) => boolean = () => true,
): ReadonlyArray<readonly [CallSpec, readonly unknown[]]> {
  return HAL_CALL_TABLE.filter(keep).map((spec) => {
    const args = (CALL_SAMPLES as Readonly<Record<string, readonly unknown[]>>)[spec.name];
    if (args === undefined) throw new Error(`the contract suite has no sample for "${spec.name}"`);
    return [spec, args] as const;
  });
}

/** Runs `spec` on `hal` with its sample arguments (a synchronous answer becomes a promise). */
export function runSample(hal: HardwareAbstractionLayer, spec: CallSpec): Promise<unknown> {
  const args = (CALL_SAMPLES as Readonly<Record<string, readonly unknown[]>>)[spec.name] ?? [];
  return invokeSpec(hal, spec, args);
}

/** The names of the table's calls, sorted (for completeness checks). */
export function tableCallNames(): string[] {
  return HAL_CALL_TABLE.map((spec) => spec.name).sort();
}
