export { runAgent } from './run-agent.js';
export type { AgentOutcome } from './agent-loop.js';
export type { AgentCaps, AgentEndpoint, AgentToolExecutor, RunAgentOptions } from './options.js';
export type { AgentDoneReason, AgentEvent, AgentEventListener } from './events.js';
export { AgentError } from './errors.js';
export type { AgentErrorCode } from './errors.js';
export { retryableStatus } from './retry.js';
export type { RetryPolicy } from './retry.js';
export type { ChatContentPart, ChatMessage, ChatTool, ChatToolCall } from './chat-types.js';
export type {
  ChatProvider,
  ChatReply,
  ChatRequest,
  ChatTurn,
  ChatUsage,
  ContextTrimmed,
} from './chat-provider.js';
export type { RetryListener } from './chat-provider.js';
export { postChatCompletion } from './chat-completions.js';
export type { ChatEndpoint } from './chat-completions.js';
