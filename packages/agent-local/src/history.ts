// The loop's chat-completions conversation as node-llama-cpp chat history: tool calls become the
// JSON the model wrote, tool results user turns, images a short text (llama.cpp's chat here takes
// none). Older turns are left out when the conversation outgrows the context window.
import type { ChatContentPart, ChatMessage } from '@hal/agent';
import type { ChatHistoryItem } from 'node-llama-cpp';
import { LocalModelError } from './errors.js';
import type { ExampleRun } from './example-run.js';

/** What a model that takes no images reads in place of a camera frame. */
export const IMAGE_PLACEHOLDER = '[camera frame not shown: this model takes no images]';

/** Most characters of one tool result the model reads (a frame's text can be long). */
const RESULT_MAX_CHARS = 800;

/** Follows the results of a turn, then the goal. */
const NEXT = 'The goal was: ';

const AFTER = 'If it is done now, reply {"answer": what you did}; if not, call the next tool.';

/** Rough per-message cost of the chat template's markers, tokens. */
const TEMPLATE_TOKENS = 8;

function partsText(content: string | ChatContentPart[]): string {
  if (typeof content === 'string') return content;
  return content.map((part) => (part.type === 'text' ? part.text : IMAGE_PLACEHOLDER)).join('\n');
}

const clip = (text: string) =>
  text.length > RESULT_MAX_CHARS ? `${text.slice(0, RESULT_MAX_CHARS)}...` : text;

/** One message as the text of a history item, or undefined for the system prompt. */
function itemOf(
  message: ChatMessage,
  toolNames: ReadonlyMap<string, string>,
): { type: 'user' | 'model'; text: string } {
  switch (message.role) {
    case 'system':
    case 'user':
      return { type: 'user', text: partsText(message.content) };
    case 'tool':
      return {
        type: 'user',
        text: `Result of ${toolNames.get(message.tool_call_id) ?? 'the tool'}: ${clip(message.content)}`,
      };
    case 'assistant': {
      const calls = (message.tool_calls ?? []).map((call) => {
        let args: unknown;
        try {
          args = JSON.parse(call.function.arguments);
        } catch {
          args = {};
        }
        return JSON.stringify({ tool: call.function.name, arguments: args });
      });
      const text =
        calls.length > 0 ? calls.join('\n') : JSON.stringify({ answer: message.content ?? '' });
      return { type: 'model', text };
    }
  }
}

/** An example run as history items: the goal, each call and its result, the answer. */
function exampleItems(example: ExampleRun): Array<{ type: 'user' | 'model'; text: string }> {
  return [
    { type: 'user', text: example.goal },
    ...example.calls.flatMap((call) => [
      {
        type: 'model' as const,
        text: JSON.stringify({ tool: call.tool, arguments: call.arguments }),
      },
      { type: 'user' as const, text: `Result of ${call.tool}: ${call.result}` },
    ]),
    { type: 'model', text: JSON.stringify({ answer: example.answer }) },
  ];
}

/** The history to generate from, and how many messages were left out to fit. */
export interface FittedHistory {
  history: ChatHistoryItem[];
  droppedMessages: number;
  promptTokens: number;
}

/**
 * Builds the chat history from `messages` (system prompt first, then the goal), with `system` as
 * the system text. When it needs more than `budgetTokens` (counted with `countTokens`), whole
 * older turns (a model reply and the results after it) are left out, oldest first; the system
 * text and the goal always stay. Throws a LocalModelError CONFIG when those two alone do not fit.
 */
export function fitHistory(
  messages: readonly ChatMessage[],
  system: string,
  budgetTokens: number,
  countTokens: (text: string) => number,
  examples: readonly ExampleRun[] = [],
): FittedHistory {
  const toolNames = new Map<string, string>();
  for (const m of messages)
    if (m.role === 'assistant')
      for (const call of m.tool_calls ?? []) toolNames.set(call.id, call.function.name);
  const [, goal, ...rest] = messages;
  const cost = (text: string) => countTokens(text) + TEMPLATE_TOKENS;
  const items = rest.map((m) => itemOf(m, toolNames));
  const costs = items.map((item) => cost(item.text));
  const shown = examples.flatMap(exampleItems);
  const fixed =
    cost(system) +
    shown.reduce((sum, item) => sum + cost(item.text), 0) +
    (goal === undefined ? 0 : cost(itemOf(goal, toolNames).text));
  if (fixed > budgetTokens) {
    throw new LocalModelError(
      'CONFIG',
      `the system prompt${examples.length > 0 ? ', its examples' : ''} and goal need about ${fixed} tokens, more than the ${budgetTokens} the context window leaves for them: give a larger context size`,
    );
  }
  let start = 0;
  let total = fixed + costs.reduce((a, b) => a + b, 0);
  while (total > budgetTokens && start < items.length) {
    // drop one whole turn: the model reply at `start` and the user turns after it
    do {
      total -= costs[start]!;
      start += 1;
    } while (start < items.length && items[start]!.type !== 'model');
  }
  const history: ChatHistoryItem[] = [{ type: 'system', text: system }];
  const push = (type: 'user' | 'model', text: string) => {
    const last = history[history.length - 1];
    if (type === 'user' && last?.type === 'user') last.text = `${last.text}\n${text}`;
    else if (type === 'user') history.push({ type: 'user', text });
    else history.push({ type: 'model', response: [text] });
  };
  for (const item of shown) push(item.type, item.text);
  const goalText = goal === undefined ? '' : itemOf(goal, toolNames).text;
  if (goal !== undefined) push('user', goalText);
  for (const item of items.slice(start)) push(item.type, item.text);
  // after results, remind the model of the goal and how to finish (small models repeat a call);
  // with worked examples, whose results are followed by nothing, the turn keeps their form (a
  // tiny model answers the reminder's quoted goal back instead of reading the result)
  if (examples.length === 0 && history[history.length - 1]?.type === 'user' && items.length > start)
    push('user', `${NEXT}${JSON.stringify(goalText)}. ${AFTER}`);
  history.push({ type: 'model', response: [] });
  return { history, droppedMessages: start, promptTokens: total };
}
