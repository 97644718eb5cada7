import { HAL_CALL_TABLE } from '@hal/types';
import type { CallSpec, CallTable } from '@hal/types';

/**
 * Every call of the HAL contract that crosses NATS, and how the gateway runs it:
 * - `queue`: one at a time, in order (motions and other commands);
 * - `priority`: at once, ahead of the queue (the safety lane, stop and e-stop, and the other
 *   commands of the safety subsystem, the e-stop's reset: never queued behind a move);
 * - `direct`: at once, beside the queue (reads, which change nothing).
 * `result` calls answer a HALToolResult; `value` calls a value or a HalError. The cached safety
 * reads are answered by the client from its own state, and `log` has a subject of its own.
 */
export type NatsCallLane = 'queue' | 'priority' | 'direct';
export type NatsCallKind = 'result' | 'value';

export interface NatsCall {
  kind: NatsCallKind;
  lane: NatsCallLane;
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

function natsLane(spec: CallSpec): NatsCallLane {
  if (spec.lane === 'safety' || (spec.subsystem === 'safety' && spec.kind === 'result')) {
    return 'priority';
  }
  return spec.kind === 'value' ? 'direct' : 'queue';
}

/** The NATS calls of a call table, by their NATS name. */
export function natsCalls(table: CallTable = HAL_CALL_TABLE): Readonly<Record<string, NatsCall>> {
  return Object.freeze(
    Object.fromEntries(
      table.filter(crossesNats).map((spec) => [
        natsCallName(spec),
        Object.freeze({
          kind: spec.kind === 'value' ? 'value' : 'result',
          lane: natsLane(spec),
          spec,
        } satisfies NatsCall),
      ]),
    ),
  );
}

/** The HAL's own calls on NATS. */
export const HAL_CALLS: Readonly<Record<string, NatsCall>> = natsCalls();
