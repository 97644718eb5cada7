import { HAL_CALL_TABLE, hasCapability } from '@hal/types';
import type { CallName, CallTable, HardwareAbstractionLayer, ReadCallName } from '@hal/types';
import type { z } from 'zod';
import { toolCatalog } from './catalog.js';
import type { ToolSafety } from './catalog.js';
import { toolParameters } from './json-schema.js';
import type { JsonSchemaObject } from './json-schema.js';
import { robotConfigOf } from './robot-config.js';

/**
 * The e-stop's parameters: the HAL never refuses an e-stop for its argument (any reason is stored
 * sanitized, a missing one becomes the default), so nothing is required and no length is a limit;
 * the reason's type and description still tell the model what to send.
 */
function neverRefused(schema: JsonSchemaObject): JsonSchemaObject {
  const properties = Object.fromEntries(
    Object.entries(schema.properties).map(([name, { type, description }]) => [
      name,
      {
        ...(type === undefined ? {} : { type }),
        ...(description === undefined ? {} : { description }),
      },
    ]),
  );
  const { required: _required, ...rest } = schema;
  return { ...rest, properties };
}

/**
 * A tool an LLM may be offered: a HAL call ({@link HalTool}) or a skill above them (`go_to`,
 * `look`: see @hal/skills). What the formats (OpenAI, Anthropic, MCP) and the agent loop need.
 */
export interface AgentTool {
  /** Stable, snake_case, e.g. 'move_forward', 'go_to', 'emergency_stop'. */
  name: string;
  /** What it does, with units, frame (REP-103) and limits. */
  description: string;
  /** JSON Schema (type 'object'); bounds are the robot's own reported limits. */
  inputSchema: JsonSchemaObject;
  /** Never blocked by the leash, approval or the rate limit. */
  safety?: ToolSafety;
  /** Whether it moves the robot (refused while e-stopped; its motions are under the leash). */
  motion: boolean;
}

/** One HAL call as an LLM tool. */
export interface HalTool extends AgentTool {
  /** The HAL call it runs. */
  call: CallName | ReadCallName;
}

/** Which tools {@link halTools} lists, by name. */
export interface HalToolsOptions {
  /** Only these tools (those the robot can run). */
  include?: string[];
  /** Not these tools. */
  exclude?: string[];
  /** The calls to make tools of; default the HAL's own call table. */
  calls?: CallTable;
}

function describe(summary: string, schema: z.ZodType, parameters: JsonSchemaObject): string {
  const own = schema.description;
  const limits = Object.entries(parameters.properties)
    .map(([name, p]) =>
      typeof p['description'] === 'string' ? `${name}: ${p['description']}` : '',
    )
    .filter((line) => line !== '');
  return [summary, own === undefined ? '' : `${own}.`, ...limits.map((l) => `${l}.`)]
    .filter((part) => part !== '')
    .join(' ');
}

/**
 * The tools an LLM may be offered for this HAL: every call the robot can run (by
 * `getDeviceInfo().capabilities`, so call it after `initialize()`), with parameter bounds from the
 * robot's own limits. The emergency stop is always offered.
 */
export function halTools(hal: HardwareAbstractionLayer, options: HalToolsOptions = {}): HalTool[] {
  const table = options.calls ?? HAL_CALL_TABLE;
  const config = robotConfigOf(hal);
  const offered = hal.getDeviceInfo().capabilities;
  return toolCatalog(table)
    .filter(
      (entry) =>
        (entry.requires === undefined ||
          entry.safety !== undefined ||
          hasCapability(offered, entry.requires)) &&
        (options.include === undefined || options.include.includes(entry.name)) &&
        !(options.exclude ?? []).includes(entry.name),
    )
    .map((entry) => {
      const spec = table.find((call) => call.name === entry.call);
      const schema = spec?.paramsSchema(config) as z.ZodType;
      const inputSchema =
        entry.safety === 'estop' ? neverRefused(toolParameters(schema)) : toolParameters(schema);
      return {
        name: entry.name,
        call: entry.call as CallName | ReadCallName,
        description: describe(entry.summary, schema, inputSchema),
        inputSchema,
        ...(entry.safety === undefined ? {} : { safety: entry.safety }),
        motion: entry.motion,
      };
    });
}
