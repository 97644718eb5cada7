import { HAL_CALL_TABLE } from '@hal/types';
import type { CallName, CallTable } from '@hal/types';

/** How a tool is gated: a stop is never blocked by the leash, approval or the rate limit. */
export type ToolSafety = 'stop' | 'estop';

/** One entry of the catalog: which HAL call a tool runs and what the robot must offer for it. */
export interface ToolEntry {
  name: string;
  call: CallName;
  /** A capability string the robot must offer; absent: every robot has the call. */
  requires?: string;
  motion: boolean;
  safety?: ToolSafety;
  /** What the tool does, ahead of the schema's own description (units, limits). */
  summary: string;
}

/** The tools of a call table, one per call, in the table's order. */
export function toolCatalog(table: CallTable): readonly ToolEntry[] {
  return Object.freeze(
    table.map((spec) => {
      const { name, summary, requires, safety } = spec.tool;
      return Object.freeze({
        name,
        // a call of an extended table is no CallName of @hal/types; it is still the call's name
        call: spec.name as CallName,
        ...(requires === undefined ? {} : { requires }),
        motion: spec.kind === 'motion',
        ...(safety === undefined ? {} : { safety }),
        summary,
      });
    }),
  );
}

/**
 * Every HAL call as a tool, in the order tools are listed (the call table's). The names are
 * stable: agents and transcripts refer to them. Units, frame and limits come from the call
 * schemas' descriptions.
 */
export const TOOL_CATALOG: readonly ToolEntry[] = toolCatalog(HAL_CALL_TABLE);

/**
 * The tool that stops the wheels (the call table's stop on the safety lane): an agent's loop
 * stops the robot with it at the end of a run, so a chosen set of tools always keeps it.
 */
export const STOP_TOOL: string = (() => {
  const stop = TOOL_CATALOG.find((tool) => tool.safety === 'stop');
  if (stop === undefined) throw new Error('the call table has no stop on the safety lane');
  return stop.name;
})();
