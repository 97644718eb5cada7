import type { ChatMessage, ChatTool } from './chat-types.js';
import type { AssistantReply } from './reply.js';

/** Told before each wait between attempts. */
export type RetryListener = (info: {
  attempt: number;
  delayMs: number;
  reason: string;
  status?: number;
}) => void;

/** What the loop asks a model for: the conversation so far and the tools it may call. */
export interface ChatRequest {
  messages: ChatMessage[];
  tools: ChatTool[];
}

/** Tokens one model request used, as the model's runtime counted them. */
export interface ChatUsage {
  promptTokens: number;
  completionTokens: number;
}

/** The conversation was shortened to fit the model's context window. */
export interface ContextTrimmed {
  /** Messages left out of this request (older turns; the system prompt and goal are kept). */
  droppedMessages: number;
  /** The prompt's size after trimming, tokens. */
  promptTokens: number;
  /** The model's context window, tokens. */
  contextTokens: number;
}

/** How one request reports back while it runs. */
export interface ChatTurn {
  /** Model requests counted from 1. */
  step: number;
  /** Aborts the request (the run was stopped, or ran out of time): generation must stop at once. */
  signal: AbortSignal;
  /** Told before each wait between attempts. */
  onRetry: RetryListener;
  /** Told each piece of text as the model produces it (providers that stream). */
  onToken(text: string): void;
  /** Told when older turns were left out of the request. */
  onContextTrimmed(info: ContextTrimmed): void;
}

/** The model's answer to one request, with its token counts when the provider knows them. */
export interface ChatReply extends AssistantReply {
  usage?: ChatUsage;
}

/**
 * A model the agent loop talks to: the OpenAI-compatible client of this package, or another
 * provider (a local model in the process, `@hal/agent-local`). Rejects with an AgentError, or
 * with `turn.signal.reason` once the signal aborts.
 */
export interface ChatProvider {
  /** Names the model in logs and events, e.g. 'openai:gpt-4o' or 'local:SmolLM2-135M'. */
  readonly name: string;
  complete(request: ChatRequest, turn: ChatTurn): Promise<ChatReply>;
}
