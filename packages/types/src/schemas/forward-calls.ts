import type {
  CommunicationInterface,
  LocomotionInterface,
  SafetyInterface,
  VisionInterface,
} from '../interfaces.js';
import { HAL_CALL_TABLE } from './call-table.js';
import type { CallSpec, CallSubsystem, CallTable } from './call-table.js';

/** The four subsystems of a HAL whose every method forwards somewhere. */
export interface ForwardedSubsystems {
  locomotion: LocomotionInterface;
  vision: VisionInterface;
  communication: CommunicationInterface;
  safety: SafetyInterface;
}

/**
 * Builds the subsystems of a HAL that forwards its calls (over a link, to another HAL): every
 * call of `table` becomes a method that runs `forward(spec, args)`. A method in `overrides`
 * (keyed by call name) replaces the forwarded one, for the few calls a forwarder answers itself.
 * The caller's types hold because the table lists every method of the interface.
 */
export function forwardCalls(
  forward: (spec: CallSpec, args: unknown[]) => unknown,
  overrides: Readonly<Record<string, (...args: never[]) => unknown>> = {},
  table: CallTable = HAL_CALL_TABLE,
): ForwardedSubsystems {
  const subsystems: Record<CallSubsystem, Record<string, unknown>> = {
    locomotion: {},
    vision: {},
    communication: {},
    safety: {},
  };
  for (const spec of table) {
    subsystems[spec.subsystem][spec.method] =
      overrides[spec.name] ?? ((...args: unknown[]) => forward(spec, args));
  }
  return subsystems as unknown as ForwardedSubsystems;
}
