import { z } from 'zod';
import { AgentError } from './errors.js';
import type { ChatToolCall } from './chat-types.js';

// What the loop reads from a chat completion; other fields are ignored. Local servers differ in
// what they fill in (some omit tool call ids or `type`), so only what the loop needs is required.
const ReplySchema = z.object({
  choices: z
    .array(
      z.object({
        message: z.object({
          content: z
            .union([z.string(), z.array(z.object({ text: z.string().optional() }).loose())])
            .nullish(),
          refusal: z.string().nullish(),
          tool_calls: z
            .array(
              z.object({
                id: z.string().nullish(),
                function: z.object({
                  name: z.string(),
                  arguments: z.union([z.string(), z.record(z.string(), z.unknown())]).nullish(),
                }),
              }),
            )
            .nullish(),
        }),
        finish_reason: z.string().nullish(),
      }),
    )
    .min(1),
  usage: z.object({ prompt_tokens: z.number(), completion_tokens: z.number() }).loose().nullish(),
});

/** The model's answer to one request. */
export interface AssistantReply {
  /** Its text ('' when it only called tools). */
  text: string;
  /** The refusal text, when the model refused. */
  refusal: string | undefined;
  /** The tool calls, each with an id (made up when the server gave none). */
  toolCalls: ChatToolCall[];
  /** The token counts the server reported, when it did. */
  usage?: { promptTokens: number; completionTokens: number };
}

/** Reads the first choice of a chat completion; throws an AgentError BAD_REPLY when it has none. */
export function parseReply(payload: unknown, step: number): AssistantReply {
  const parsed = ReplySchema.safeParse(payload);
  if (!parsed.success) {
    throw new AgentError('BAD_REPLY', 'the endpoint answered without a chat completion message', {
      details: { issues: parsed.error.issues.slice(0, 3) },
    });
  }
  const message = parsed.data.choices[0]!.message;
  const content = message.content;
  const text =
    typeof content === 'string' ? content : (content ?? []).map((part) => part.text ?? '').join('');
  const toolCalls = (message.tool_calls ?? []).map((call, index) => {
    const args = call.function.arguments;
    return {
      id: call.id ?? `call_${step}_${index}`,
      type: 'function' as const,
      function: {
        name: call.function.name,
        // Some servers send the arguments as an object; the conversation carries a string.
        arguments: typeof args === 'string' ? args : JSON.stringify(args ?? {}),
      },
    };
  });
  const usage = parsed.data.usage;
  return {
    text,
    refusal: message.refusal ?? undefined,
    toolCalls,
    ...(usage == null
      ? {}
      : {
          usage: { promptTokens: usage.prompt_tokens, completionTokens: usage.completion_tokens },
        }),
  };
}
