import { AttemptError } from './llm-attempt-error.js';
import { parseDecision } from './schema.js';
import type { DecisionBounds, NavigationDecision } from './schema.js';

/** Takes the JSON object out of a reply, tolerating code fences and text around it. */
export function extractJson(content: string): unknown {
  const trimmed = content.trim();
  const fenced = /^```(?:json)?\s*([\s\S]*?)\s*```$/i.exec(trimmed);
  const text = fenced?.[1] ?? trimmed;
  try {
    return JSON.parse(text);
  } catch (error) {
    const start = text.indexOf('{');
    const end = text.lastIndexOf('}');
    if (start !== -1 && end > start) return JSON.parse(text.slice(start, end + 1));
    throw error;
  }
}

/**
 * The text of a chat-completions response's `choices[0].message.content` (a string, or a list
 * of parts whose text is joined); an AttemptError when there is none or the model refused.
 */
export function replyContent(payload: unknown): string {
  const message = (
    payload as { choices?: { message?: { content?: unknown; refusal?: unknown } }[] }
  ).choices?.[0]?.message;
  const content = message?.content;
  if (typeof content === 'string') return content;
  // Some servers give the content as a list of parts.
  if (Array.isArray(content)) {
    const text = content
      .map((part: unknown) =>
        typeof part === 'object' &&
        part !== null &&
        typeof (part as { text?: unknown }).text === 'string'
          ? (part as { text: string }).text
          : '',
      )
      .join('');
    if (text !== '') return text;
  }
  if (typeof message?.refusal === 'string') {
    throw new AttemptError(`the model refused: ${message.refusal.slice(0, 200)}`, true);
  }
  throw new AttemptError('the reply has no choices[0].message.content text', true);
}

/**
 * The decision in a reply, checked with the decision schema within `bounds`; an AttemptError
 * whose feedback tells the model what was wrong when the reply is not JSON or breaks the schema.
 */
export function parseReply(content: string, bounds: DecisionBounds): NavigationDecision {
  let value: unknown;
  try {
    value = extractJson(content);
  } catch {
    throw new AttemptError(
      'the reply was not valid JSON',
      true,
      'Your reply was not valid JSON. Answer with only the JSON object.',
    );
  }
  const parsed = parseDecision(value, bounds);
  if (!parsed.ok) {
    throw new AttemptError(
      `the reply broke the decision schema (${parsed.problem})`,
      true,
      `Your reply does not match the schema: ${parsed.problem}. Answer again with only a valid JSON object.`,
    );
  }
  return parsed.decision;
}
