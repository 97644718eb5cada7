import { HAL_CALL_TABLE } from '@hal/types';
import type { CallSpec, CallTable } from '@hal/types';

/**
 * Every call of the HAL contract that crosses NATS. `result` calls answer a HALToolResult;
 * `value` calls a value or a HalError. The gateway runs them in their lanes (`ServedCalls`:
 * stop, e-stop and its reset at once, commands in order, reads beside them). The cached safety
 * reads are answered by the client from its own state, and `log` has a subject of its own.
 */
export type NatsCallKind = 'result' | 'value';

export interface NatsCall {
  kind: NatsCallKind;
  spec: CallSpec;
}

/** A call's name on NATS: `{subsystem}.{method}`, e.g. `locomotion.moveForward`. */
export function natsCallName(spec: CallSpec): string {
  return `${spec.subsystem}.${spec.method}`;
}

/** Whether a call of the table crosses NATS as a call. */
export function crossesNats(spec: CallSpec): boolean {
  return spec.kind !== 'void' && !spec.cached;
}

/** The NATS calls of a call table, by their NATS name. */
export function natsCalls(table: CallTable = HAL_CALL_TABLE): Readonly<Record<string, NatsCall>> {
  return Object.freeze(
    Object.fromEntries(
      table.filter(crossesNats).map((spec) => [
        natsCallName(spec),
        Object.freeze({
          kind: spec.kind === 'value' ? 'value' : 'result',
          spec,
        } satisfies NatsCall),
      ]),
    ),
  );
}
