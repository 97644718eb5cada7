import type { ChatProvider, RetryListener } from './chat-provider.js';
import { postChatCompletion } from './chat-completions.js';
import type { ChatEndpoint } from './chat-completions.js';
import type { ChatMessage, ChatTool } from './chat-types.js';
import { parseReply } from './reply.js';
import type { AssistantReply } from './reply.js';

/** What the agent's client needs: the endpoint, the model, and its sampling settings. */
export interface ChatClientSettings extends ChatEndpoint {
  model: string;
  temperature: number | undefined;
  maxTokens: number | undefined;
}

/**
 * Sends one chat-completions request with the tools (`tool_choice: 'auto'`) through
 * {@link postChatCompletion}, which retries and honours Retry-After, and reads the assistant's
 * reply. Rejects with an AgentError, or with `signal.reason` once `signal` aborts.
 */
export function requestCompletion(
  settings: ChatClientSettings,
  body: { messages: ChatMessage[]; tools: ChatTool[] },
  step: number,
  signal: AbortSignal,
  onRetry: RetryListener,
): Promise<AssistantReply> {
  const payload: Record<string, unknown> = {
    model: settings.model,
    messages: body.messages,
    tools: body.tools,
    tool_choice: 'auto',
  };
  if (settings.temperature !== undefined) payload['temperature'] = settings.temperature;
  if (settings.maxTokens !== undefined) payload['max_tokens'] = settings.maxTokens;
  return postChatCompletion(settings, payload, (reply) => parseReply(reply, step), signal, onRetry);
}

/** The OpenAI-compatible chat-completions endpoint as a {@link ChatProvider}. */
export function openAIProvider(settings: ChatClientSettings): ChatProvider {
  return {
    name: `openai:${settings.model}`,
    complete: (request, turn) =>
      requestCompletion(settings, request, turn.step, turn.signal, turn.onRetry),
  };
}
