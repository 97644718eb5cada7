import { errorResult, TOOL_CATALOG } from '@hal/tools';
import type { AgentTool, ToolCall, ToolExecutor, ToolResult } from '@hal/tools';
import type { SkillSet } from './skill-set.js';

/** Which tools an agent is offered. */
export const TOOL_PROFILES = ['skills', 'primitives', 'all'] as const;
export type ToolProfile = (typeof TOOL_PROFILES)[number];

/** What a profile offers: the tools and how to run them. */
export interface ProfileTools {
  readonly profile: ToolProfile;
  readonly tools: AgentTool[];
  execute(call: ToolCall): Promise<ToolResult>;
}

/** What interrupts the skill running: the safety tools of the call table (the stop, the e-stop). */
const SAFETY: ReadonlySet<string> = new Set(
  TOOL_CATALOG.filter((tool) => tool.safety !== undefined).map((tool) => tool.name),
);
/**
 * The HAL tools the skills profile keeps: the stop, the e-stop, and its reset (an instruction may
 * allow one; whether the agent resets when told not to is what a safety task measures).
 */
const KEPT: ReadonlySet<string> = new Set(
  TOOL_CATALOG.filter((tool) => SAFETY.has(tool.name) || tool.call === 'resetEmergencyStop').map(
    (tool) => tool.name,
  ),
);

/** Whether `text` names a profile. */
export function isToolProfile(text: string): text is ToolProfile {
  return (TOOL_PROFILES as readonly string[]).includes(text);
}

/**
 * The tools of `profile`: `skills` (the skills, the stop, the e-stop and its reset: a few tools with short
 * descriptions, for small models), `primitives` (the HAL's calls as tools) or `all` (both). A stop
 * or an e-stop first interrupts the skill running, then goes to the robot as the primitive does.
 */
export function toolProfile(
  profile: ToolProfile,
  primitives: Pick<ToolExecutor, 'tools' | 'execute'>,
  skills: SkillSet,
): ProfileTools {
  if (profile === 'primitives') {
    return { profile, tools: primitives.tools, execute: (call) => primitives.execute(call) };
  }
  const kept =
    profile === 'all' ? primitives.tools : primitives.tools.filter((t) => KEPT.has(t.name));
  const skillNames = new Set(skills.tools.map((t) => t.name));
  const clash = kept.find((t) => skillNames.has(t.name));
  if (clash !== undefined)
    throw new RangeError(`a skill and a HAL tool are both called "${clash.name}"`);
  const hal = new Set(kept.map((t) => t.name));
  return {
    profile,
    tools: [...skills.tools, ...kept],
    execute: async (call) => {
      if (SAFETY.has(call.name)) skills.interrupt();
      if (skillNames.has(call.name)) return skills.execute(call);
      if (hal.has(call.name)) return primitives.execute(call);
      return errorResult('UNKNOWN_TOOL', `no tool "${call.name}" in the ${profile} profile`);
    },
  };
}
