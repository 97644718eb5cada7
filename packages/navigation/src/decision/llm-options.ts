import { scoped, silentLogger } from '@hal/types';
import type { Logger, ScopedLogger } from '@hal/types';
import { NavigationError, positiveOption } from '../errors.js';
import type { DecisionProvider } from './provider.js';

/** How the provider asks the server for JSON. */
export type ResponseFormatMode = 'json_schema' | 'json_object' | 'none';

/** Options of an {@link OpenAICompatibleProvider}. */
export interface OpenAICompatibleOptions {
  /** Base URL of the API, up to and including `/v1`. Default env OPENAI_BASE_URL, else OpenAI's. */
  baseUrl?: string;
  /** Bearer token. Default env OPENAI_API_KEY; local servers need none. */
  apiKey?: string;
  /** Model name. Default env NAV_MODEL; required one way or the other. */
  model?: string;
  /** Time allowed for one HTTP request, ms. Default 30000. */
  timeoutMs?: number;
  /** Requests per decision before giving up (invalid replies and retryable errors). Default 3. */
  maxAttempts?: number;
  /** Sampling temperature. Default 0.2. */
  temperature?: number;
  /** Most tokens in a reply. Default 500. */
  maxTokens?: number;
  /**
   * `json_schema` (default): structured output with the decision's JSON Schema; `json_object`:
   * any JSON object (the schema is in the prompt); `none`: no response_format at all. A server
   * that rejects `json_schema` with HTTP 400 is asked again with `json_object`.
   */
  responseFormat?: ResponseFormatMode;
  /** Send the camera frame as an image. Default true. */
  sendFrame?: boolean;
  /**
   * Also send a small picture of the occupancy grid (route, robot, goal) as a second image.
   * Default false. Node only (the JPEG encoder needs `Buffer`).
   */
  sendMapImage?: boolean;
  /** Asked when no valid decision came from the model (the reasoning says so). */
  fallback?: DecisionProvider;
  /** Replaces the built-in system prompt. */
  systemPrompt?: string;
  /** The fetch to use. Default the global one. */
  fetch?: typeof fetch;
  /** Environment to read defaults from. Default `process.env` where there is one. */
  env?: Record<string, string | undefined>;
  /** Where to log (namespace `hal:navigation:llm`). Default silent. */
  logger?: Logger;
}

/** The provider's options with the environment read, the defaults filled in and all checked. */
export interface LlmSettings {
  /** The chat-completions endpoint: `{baseUrl}/chat/completions`. */
  readonly url: string;
  readonly apiKey: string | undefined;
  readonly model: string;
  readonly timeoutMs: number;
  readonly maxAttempts: number;
  readonly temperature: number;
  readonly maxTokens: number;
  readonly responseFormat: ResponseFormatMode;
  readonly sendFrame: boolean;
  readonly sendMapImage: boolean;
  readonly fallback: DecisionProvider | undefined;
  /** The system prompt, when it replaces the built-in one. */
  readonly systemPrompt: string | undefined;
  readonly fetch: typeof fetch;
  readonly logger: ScopedLogger;
}

const DEFAULT_BASE_URL = 'https://api.openai.com/v1';

function readEnv(): Record<string, string | undefined> {
  const process = (globalThis as { process?: { env?: Record<string, string | undefined> } })
    .process;
  return process?.env ?? {};
}

/** Reads the defaults from the environment and checks the options; throws CONFIG NavigationErrors. */
export function resolveLlmSettings(options: OpenAICompatibleOptions): LlmSettings {
  const env = options.env ?? readEnv();
  const model = options.model ?? env['NAV_MODEL'];
  if (model === undefined || model.trim() === '') {
    throw new NavigationError(
      'CONFIG',
      'OpenAICompatibleProvider: "model" is required (pass it, or set NAV_MODEL)',
    );
  }
  const baseUrl = (options.baseUrl ?? env['OPENAI_BASE_URL'] ?? DEFAULT_BASE_URL).replace(
    /\/+$/,
    '',
  );
  try {
    new URL(baseUrl);
  } catch (cause) {
    throw new NavigationError(
      'CONFIG',
      `OpenAICompatibleProvider: "baseUrl" must be an absolute URL, got ${JSON.stringify(baseUrl)}`,
      { cause },
    );
  }
  const timeoutMs = positiveOption('timeoutMs', options.timeoutMs ?? 30_000);
  const maxAttempts = options.maxAttempts ?? 3;
  if (!Number.isInteger(maxAttempts) || maxAttempts < 1 || maxAttempts > 10)
    throw new NavigationError(
      'CONFIG',
      `"maxAttempts" must be an integer from 1 to 10, got ${maxAttempts}`,
    );
  const fetchImpl = options.fetch ?? globalThis.fetch;
  if (typeof fetchImpl !== 'function')
    throw new NavigationError('CONFIG', 'no fetch available: pass "fetch"');
  return {
    url: `${baseUrl}/chat/completions`,
    apiKey: options.apiKey ?? env['OPENAI_API_KEY'],
    model,
    timeoutMs,
    maxAttempts,
    temperature: options.temperature ?? 0.2,
    maxTokens: options.maxTokens ?? 500,
    responseFormat: options.responseFormat ?? 'json_schema',
    sendFrame: options.sendFrame ?? true,
    sendMapImage: options.sendMapImage ?? false,
    fallback: options.fallback,
    systemPrompt: options.systemPrompt,
    fetch: fetchImpl,
    logger: scoped(options.logger ?? silentLogger, 'hal:navigation:llm'),
  };
}
