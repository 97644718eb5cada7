import type { ChatReply } from '@hal/agent';
import { LocalModelError } from './errors.js';

/**
 * Reads the model's grammar-constrained reply: `{"tool", "arguments"}` is a tool call (its
 * arguments are validated by the tool when it runs), `{"answer"}` the text that ends the run,
 * cut to `answerMaxLength` characters (a length the grammar could not hold). Throws a
 * LocalModelError GENERATION when the reply is not one of them (it was cut short).
 */
export function readReply(
  json: string,
  step: number,
  cutShort: boolean,
  answerMaxLength = Number.POSITIVE_INFINITY,
): Omit<ChatReply, 'usage'> {
  let value: unknown;
  try {
    value = JSON.parse(json);
  } catch (cause) {
    throw new LocalModelError(
      'GENERATION',
      cutShort
        ? `the reply was cut off at the token limit before it was complete: ${JSON.stringify(json.slice(0, 120))}`
        : `the reply is not JSON: ${JSON.stringify(json.slice(0, 120))}`,
      { cause },
    );
  }
  const reply = value as { tool?: unknown; arguments?: unknown; answer?: unknown };
  if (typeof reply.tool === 'string') {
    return {
      text: '',
      refusal: undefined,
      toolCalls: [
        {
          id: `call_${step}_0`,
          type: 'function',
          function: { name: reply.tool, arguments: JSON.stringify(reply.arguments ?? {}) },
        },
      ],
    };
  }
  if (typeof reply.answer === 'string')
    return { text: reply.answer.slice(0, answerMaxLength), refusal: undefined, toolCalls: [] };
  throw new LocalModelError(
    'GENERATION',
    `the reply is neither a tool call nor an answer: ${json}`,
  );
}
