// The tools `hal mcp --tools` offers: the HAL's calls through the executor (the leash, timeouts),
// the skills over that same executor, or both. Built once per run: over HTTP every session gets
// a fresh MCP server, but the skills' memory of what the robot saw lasts the whole run.
import { approveOverMcp } from '@hal/mcp';
import type { ApprovalPolicy, OfferedTools } from '@hal/mcp';
import { createSkills, toolProfile } from '@hal/skills';
import type { ToolProfile } from '@hal/skills';
import { createToolExecutor, halTools, toolBackedHal } from '@hal/tools';
import type { Leash } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';

/** How the tools run. */
export interface OfferedToolsOptions {
  profile: ToolProfile;
  leash: Leash;
  /** Who approves motions; anything but none puts the MCP approval hook in the leash. */
  approve?: ApprovalPolicy;
  /** Time one HAL call may take, ms (motions get more). */
  timeoutMs?: number;
}

/**
 * The tools of `options.profile` over `hal` (the robot as the model drives it: guarded, maybe
 * recorded). Every HAL call a skill makes is a tool call of the same executor the primitives run
 * through, so the skills meet the leash, the timeouts and the guard as a model's own calls do.
 */
export function offeredTools(
  hal: HardwareAbstractionLayer,
  options: OfferedToolsOptions,
): OfferedTools {
  const primitives = createToolExecutor(hal, {
    tools: halTools(hal),
    leash:
      options.approve === undefined || options.approve === 'none'
        ? options.leash
        : { ...options.leash, approve: approveOverMcp },
    ...(options.timeoutMs === undefined ? {} : { timeoutMs: options.timeoutMs }),
  });
  if (options.profile === 'primitives') return primitives;
  const skills = createSkills(toolBackedHal(hal, (call) => primitives.execute(call)));
  return toolProfile(options.profile, primitives, skills);
}
