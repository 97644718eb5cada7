import type { ChatTool } from '@hal/agent';

/**
 * A system prompt for small local models: short, since every token is read on a CPU and a
 * 135M-parameter model loses the thread in the long built-in prompt. The reply format and the
 * tool list follow it in the prompt the model sees.
 */
export const LOCAL_SYSTEM_PROMPT = 'You control a small robot with tools.';

/**
 * The tools a small model is offered by default: few, since a tiny model picks among many badly.
 * The agent loop can still run `stop` at the end of a run whatever the model was offered.
 */
export const SMALL_MODEL_TOOLS: readonly string[] = Object.freeze([
  'move_forward',
  'move_backward',
  'rotate',
  'get_pose',
]);

/** How the model is told to reply; the grammar makes it so. */
const FORMAT =
  'Reply with one JSON object: {"tool": name, "arguments": {...}} to call a tool, or {"answer": text} when the goal is done.';

/** The system text the model reads: the loop's system prompt, the reply format, the tools. */
export function systemText(systemPrompt: string, tools: readonly ChatTool[]): string {
  const lines = tools.map(({ function: fn }) => `- ${fn.name}: ${fn.description}`);
  return [systemPrompt, FORMAT, ...(lines.length === 0 ? [] : ['Tools:', ...lines])].join('\n');
}
