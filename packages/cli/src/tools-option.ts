// `--tools` of hal agent and hal eval: a tool profile (skills, primitives, all) or the names of
// HAL tools, comma-separated (the primitives, narrowed: what `--tools` took before there were
// profiles).
import { isToolProfile, TOOL_PROFILES } from '@hal/skills';
import type { ToolProfile } from '@hal/skills';
import { CliError } from './cli-error.js';

/** What `--tools` named: a profile, or HAL tool names. */
export type ToolsChoice = { profile: ToolProfile } | { names: readonly string[] };

/** Reads `--tools`; USAGE for an empty list or a profile among tool names. */
export function toolsChoice(text: string | undefined): ToolsChoice | undefined {
  if (text === undefined) return undefined;
  const trimmed = text.trim();
  if (isToolProfile(trimmed)) return { profile: trimmed };
  const names = trimmed
    .split(',')
    .map((name) => name.trim())
    .filter((name) => name !== '');
  if (names.length === 0)
    throw new CliError(
      'USAGE',
      `"--tools" must be a profile (${TOOL_PROFILES.join(', ')}) or HAL tool names separated by commas`,
    );
  const profile = names.find((n) => isToolProfile(n));
  if (profile !== undefined)
    throw new CliError(
      'USAGE',
      `"--tools": "${profile}" is a profile: give a profile alone (${TOOL_PROFILES.join(', ')}) or tool names, not both`,
    );
  return { names };
}
