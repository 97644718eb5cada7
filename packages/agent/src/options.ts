import type { AgentTool, Leash, ToolCall, ToolResult } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { scoped, silentLogger } from '@hal/types';
import type { Logger, ScopedLogger } from '@hal/types';
import { AgentError } from './errors.js';
import { openAIProvider } from './chat-client.js';
import type { ChatClientSettings } from './chat-client.js';
import type { ChatProvider } from './chat-provider.js';
import type { AgentEventListener } from './events.js';
import { DEFAULT_RETRY } from './retry.js';
import type { RetryPolicy } from './retry.js';

/** An OpenAI-compatible chat-completions endpoint. */
export interface AgentEndpoint {
  /** Base URL up to and including `/v1`, e.g. `https://api.openai.com/v1`, `http://127.0.0.1:11434/v1`. */
  baseUrl: string;
  /** The model name; it must support tool calling (and images, to see camera frames). */
  model: string;
  /** Bearer token; local servers usually need none. Sent to `baseUrl` only. */
  apiKey?: string;
}

/** When a run stops by itself. */
export interface AgentCaps {
  /** Most model requests in one run. Default 20. */
  maxSteps: number;
  /** Most time for the whole run, ms (model requests, waits and tool calls). Default 300000. */
  maxMs: number;
}

/** Runs the tool calls: `createToolExecutor(hal)` from `@hal/tools`, or your own. */
export interface AgentToolExecutor {
  tools: readonly AgentTool[];
  /** Runs one call; never throws (errors are results the model reads). */
  execute(call: ToolCall): Promise<ToolResult>;
}

/** Options of {@link runAgent}. Give `hal` or `executor`. */
export interface RunAgentOptions {
  /** What the robot should do, in words. */
  goal: string;
  /** The robot: its tools come from `halTools(hal)`, run by `createToolExecutor`. */
  hal?: HardwareAbstractionLayer;
  /** Runs the tool calls instead of a default executor over `hal` (e.g. one with a leash). */
  executor?: AgentToolExecutor;
  /** With `hal`: the leash of the default executor (approval, caps, geofence, rate limit). */
  leash?: Leash;
  /** With `hal`: the time allowed for one tool call, ms (the executor's default otherwise). */
  toolTimeoutMs?: number;
  /** An OpenAI-compatible endpoint. Give `endpoint` or `provider`. */
  endpoint?: AgentEndpoint;
  /** Any other model, e.g. a local one (`createLocalChatProvider` of `@hal/agent-local`). */
  provider?: ChatProvider;
  caps?: Partial<AgentCaps>;
  /** Stops the run (and the robot, when a motion is under way). */
  signal?: AbortSignal;
  /** Receives the run's events as they happen. */
  onEvent?: AgentEventListener;
  /** With `endpoint`: time allowed for one HTTP request, ms. Default 60000. */
  requestTimeoutMs?: number;
  /** With `endpoint`: retries of HTTP 408/429/5xx, network errors and timeouts. */
  retry?: Partial<RetryPolicy>;
  /** Replaces the built-in system prompt. */
  systemPrompt?: string;
  /** With `endpoint`: sampling temperature; the server's default when absent. */
  temperature?: number;
  /** With `endpoint`: most tokens in one reply (`max_tokens`); the server's default when absent. */
  maxTokens?: number;
  /** With `endpoint`: the fetch to use. Default the global one. */
  fetch?: typeof fetch;
  logger?: Logger;
}

export const DEFAULT_CAPS: AgentCaps = Object.freeze({ maxSteps: 20, maxMs: 300_000 });

/** The options checked, with the defaults filled in. */
export interface AgentSettings {
  goal: string;
  /** The model: the endpoint's client, or the caller's provider. */
  provider: ChatProvider;
  caps: AgentCaps;
  logger: ScopedLogger;
}

function positive(name: string, value: number, integer = false): number {
  if (!Number.isFinite(value) || value <= 0 || (integer && !Number.isInteger(value))) {
    throw new AgentError(
      'CONFIG',
      `"${name}" must be a positive ${integer ? 'integer' : 'number'}, got ${value}`,
    );
  }
  return value;
}

/** Checks the options; throws an AgentError CONFIG naming the first bad one. */
export function resolveSettings(options: RunAgentOptions): AgentSettings {
  if (typeof options.goal !== 'string' || options.goal.trim() === '')
    throw new AgentError('CONFIG', '"goal" must be a non-empty string');
  if (options.endpoint !== undefined && options.provider !== undefined)
    throw new AgentError('CONFIG', 'give "endpoint" or "provider", not both');
  const caps = { ...DEFAULT_CAPS, ...options.caps };
  positive('caps.maxSteps', caps.maxSteps, true);
  positive('caps.maxMs', caps.maxMs);
  let provider = options.provider;
  if (provider !== undefined && typeof provider.complete !== 'function')
    throw new AgentError('CONFIG', '"provider" must have a complete() method');
  provider ??= openAIProvider(endpointSettings(options));
  return {
    goal: options.goal,
    provider,
    caps,
    logger: scoped(options.logger ?? silentLogger, 'hal:agent'),
  };
}

/** The OpenAI-compatible client's settings, checked. */
function endpointSettings(options: RunAgentOptions): ChatClientSettings {
  const { endpoint } = options;
  if (endpoint === undefined)
    throw new AgentError('CONFIG', 'give "endpoint" or "provider": the agent needs a model');
  if (typeof endpoint.model !== 'string' || endpoint.model.trim() === '')
    throw new AgentError('CONFIG', '"endpoint.model" must be a non-empty string');
  const baseUrl = String(endpoint.baseUrl ?? '').replace(/\/+$/, '');
  let parsed: URL;
  try {
    parsed = new URL(baseUrl);
  } catch (cause) {
    throw new AgentError(
      'CONFIG',
      `"endpoint.baseUrl" must be an absolute URL, got ${JSON.stringify(endpoint.baseUrl)}`,
      { cause },
    );
  }
  if (parsed.protocol !== 'http:' && parsed.protocol !== 'https:')
    throw new AgentError('CONFIG', `"endpoint.baseUrl" must be http or https, got ${baseUrl}`);
  const retry = { ...DEFAULT_RETRY, ...options.retry };
  if (!Number.isInteger(retry.maxRetries) || retry.maxRetries < 0 || retry.maxRetries > 10)
    throw new AgentError(
      'CONFIG',
      `"retry.maxRetries" must be an integer from 0 to 10, got ${retry.maxRetries}`,
    );
  positive('retry.baseDelayMs', retry.baseDelayMs);
  positive('retry.maxDelayMs', retry.maxDelayMs);
  const fetchImpl = options.fetch ?? globalThis.fetch;
  if (typeof fetchImpl !== 'function')
    throw new AgentError('CONFIG', 'no fetch available: pass "fetch"');
  return {
    url: `${baseUrl}/chat/completions`,
    model: endpoint.model,
    apiKey: endpoint.apiKey,
    requestTimeoutMs: positive('requestTimeoutMs', options.requestTimeoutMs ?? 60_000),
    retry,
    temperature: options.temperature,
    maxTokens:
      options.maxTokens === undefined ? undefined : positive('maxTokens', options.maxTokens, true),
    // Bound to globalThis: a browser's fetch throws "Illegal invocation" when called as a method.
    fetch: options.fetch ?? ((input, init) => fetchImpl(input, init)),
  };
}
