import { gridImageDataUrl } from '../grid/image.js';
import { describeWorld } from '../grid/summary.js';
import { NavigationError, SILENT_LOGGER } from '../errors.js';
import type { NavigationLogger } from '../errors.js';
import type { DecisionContext, DecisionProvider } from './provider.js';
import { decisionJsonSchema, parseDecision } from './schema.js';
import type { DecisionBounds, NavigationDecision } from './schema.js';

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
  logger?: NavigationLogger;
}

const DEFAULT_BASE_URL = 'https://api.openai.com/v1';

const SYSTEM_PROMPT = [
  'You steer a small differential-drive robot to a goal. Each turn you get what its camera sees,',
  'a summary of its occupancy-grid map and the result of your previous action, and you answer',
  'with ONE decision as a JSON object matching the given schema, nothing else.',
  'Actions: MOVE_TO {x, y} drives to a point along an obstacle-free route the planner finds',
  '(give the goal itself, or an intermediate point in known free space); EXPLORE visits the',
  'nearest unexplored area; ROTATE_TO {yaw_deg} turns in place to an ABSOLUTE heading in',
  'degrees, counter-clockwise from +x (0 = +x/east, 90 = +y/north); STOP ends the run.',
  'Set goal_reached to true only when the robot is within the goal tolerance, with STOP.',
  'Coordinates are metres in the world frame: x east, y north.',
].join(' ');

function readEnv(): Record<string, string | undefined> {
  const process = (globalThis as { process?: { env?: Record<string, string | undefined> } })
    .process;
  return process?.env ?? {};
}

/** Thrown inside one attempt: says whether another attempt may help. */
class AttemptError extends Error {
  constructor(
    message: string,
    readonly retryable: boolean,
    readonly feedback?: string,
  ) {
    super(message);
  }
}

/** Waits `ms`, or less when `signal` aborts. */
function pause(ms: number, signal: AbortSignal): Promise<void> {
  return new Promise((resolve) => {
    const done = () => {
      clearTimeout(timer);
      signal.removeEventListener('abort', done);
      resolve();
    };
    const timer = setTimeout(done, ms);
    signal.addEventListener('abort', done, { once: true });
  });
}

/** Takes the JSON object out of a reply, tolerating code fences and text around it. */
function extractJson(content: string): unknown {
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

type ContentPart =
  { type: 'text'; text: string } | { type: 'image_url'; image_url: { url: string } };
type ChatMessage =
  | { role: 'system' | 'assistant'; content: string }
  | { role: 'user'; content: string | ContentPart[] };

/**
 * A decision provider backed by any OpenAI-compatible chat-completions endpoint (OpenAI, vLLM,
 * Ollama, llama.cpp server, LM Studio, ...). Each decision sends the camera frame as an image,
 * the world summary, the goal and the previous result, asks for the decision's JSON Schema as
 * structured output, and validates the reply with zod. A reply that is not JSON or breaks the
 * schema is answered with the problem and asked again; a timeout, HTTP 429 or 5xx is retried;
 * when no attempt gives a valid decision the fallback provider decides (or the call rejects with
 * a NavigationError PROVIDER_ERROR).
 */
export class OpenAICompatibleProvider implements DecisionProvider {
  readonly name: string;
  readonly wantsFrame: boolean;
  readonly #sendMapImage: boolean;
  readonly #url: string;
  readonly #apiKey: string | undefined;
  readonly #model: string;
  readonly #timeoutMs: number;
  readonly #maxAttempts: number;
  readonly #temperature: number;
  readonly #maxTokens: number;
  #format: ResponseFormatMode;
  readonly #fallback: DecisionProvider | undefined;
  readonly #system: string;
  readonly #fetch: typeof fetch;
  readonly #logger: NavigationLogger;

  constructor(options: OpenAICompatibleOptions = {}) {
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
    const timeoutMs = options.timeoutMs ?? 30_000;
    if (!Number.isFinite(timeoutMs) || timeoutMs <= 0)
      throw new NavigationError(
        'CONFIG',
        `"timeoutMs" must be a positive number, got ${timeoutMs}`,
      );
    const maxAttempts = options.maxAttempts ?? 3;
    if (!Number.isInteger(maxAttempts) || maxAttempts < 1 || maxAttempts > 10)
      throw new NavigationError(
        'CONFIG',
        `"maxAttempts" must be an integer from 1 to 10, got ${maxAttempts}`,
      );
    const fetchImpl = options.fetch ?? globalThis.fetch;
    if (typeof fetchImpl !== 'function')
      throw new NavigationError('CONFIG', 'no fetch available: pass "fetch"');
    this.#url = `${baseUrl}/chat/completions`;
    this.#apiKey = options.apiKey ?? env['OPENAI_API_KEY'];
    this.#model = model;
    this.#timeoutMs = timeoutMs;
    this.#maxAttempts = maxAttempts;
    this.#temperature = options.temperature ?? 0.2;
    this.#maxTokens = options.maxTokens ?? 500;
    this.#format = options.responseFormat ?? 'json_schema';
    this.#fallback = options.fallback;
    this.#system = options.systemPrompt ?? SYSTEM_PROMPT;
    this.#fetch = fetchImpl;
    this.#logger = options.logger ?? SILENT_LOGGER;
    this.wantsFrame = options.sendFrame ?? true;
    this.#sendMapImage = options.sendMapImage ?? false;
    this.name = `llm:${model}`;
  }

  async decide(context: DecisionContext, signal: AbortSignal): Promise<NavigationDecision> {
    const bounds = this.#bounds(context);
    const schema = decisionJsonSchema(bounds);
    const messages: ChatMessage[] = [
      { role: 'system', content: this.#system },
      { role: 'user', content: this.#userContent(context, schema) },
    ];
    const problems: string[] = [];
    let builtFor = this.#format;
    for (let attempt = 1; attempt <= this.#maxAttempts; attempt += 1) {
      if (signal.aborted) throw this.#aborted(signal);
      if (builtFor !== this.#format) {
        // The server refused structured output: the schema now goes in the prompt.
        messages[1] = { role: 'user', content: this.#userContent(context, schema) };
        builtFor = this.#format;
      }
      let reply: string | undefined;
      try {
        const content = await this.#request(messages, schema, signal);
        reply = content;
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
      } catch (error) {
        if (signal.aborted) throw this.#aborted(signal);
        const failure =
          error instanceof AttemptError
            ? error
            : new AttemptError(error instanceof Error ? error.message : String(error), false);
        problems.push(`attempt ${attempt}: ${failure.message}`);
        this.#logger.warn('navigation decision attempt failed', {
          provider: this.name,
          attempt,
          problem: failure.message,
        });
        if (!failure.retryable) break;
        if (failure.feedback !== undefined && reply !== undefined) {
          const last = messages.at(-1);
          // Keep the conversation short: one correction at a time.
          if (last?.role === 'user' && typeof last.content === 'string') messages.splice(-2, 2);
          messages.push({ role: 'assistant', content: reply.slice(0, 2000) });
          messages.push({ role: 'user', content: failure.feedback });
        } else if (attempt < this.#maxAttempts) {
          await pause(250 * attempt, signal);
        }
      }
    }
    const why = problems.join('; ');
    if (this.#fallback !== undefined) {
      this.#logger.warn('navigation decision falls back', { provider: this.name, why });
      const decision = await this.#fallback.decide(context, signal);
      return {
        ...decision,
        reasoning: `[fallback ${this.#fallback.name}: ${why}] ${decision.reasoning}`.slice(0, 2000),
      };
    }
    throw new NavigationError('PROVIDER_ERROR', `${this.name}: no valid decision (${why})`, {
      details: { problems },
    });
  }

  #bounds(context: DecisionContext): DecisionBounds {
    const { spec } = context.grid;
    const round = (v: number) => Math.round(v * 1000) / 1000;
    return {
      minX: round(spec.originX),
      maxX: round(spec.originX + spec.width * spec.resolutionM),
      minY: round(spec.originY),
      maxY: round(spec.originY + spec.height * spec.resolutionM),
    };
  }

  #userContent(context: DecisionContext, schema: Record<string, unknown>): ContentPart[] {
    const lines = [
      `Cycle ${context.cycle}.`,
      context.goal === null
        ? 'Mission: explore the area; STOP with goal_reached true when nothing is left to explore.'
        : `Mission: reach the goal (${context.goal.x.toFixed(2)}, ${context.goal.y.toFixed(
            2,
          )}) m, within ${context.goalToleranceM.toFixed(2)} m.`,
    ];
    const last = context.lastResult;
    if (last !== undefined) {
      lines.push(
        `Previous action ${last.action}: ${last.success ? 'succeeded' : `failed (${last.code ?? 'error'}: ${last.error ?? 'no message'})`}.`,
      );
    }
    const options: Parameters<typeof describeWorld>[1] = {
      pose: context.pose,
      goal: context.goal,
    };
    if (context.readings !== undefined) options.readings = context.readings;
    lines.push(describeWorld(context.grid, options));
    if (this.#format !== 'json_schema') {
      lines.push(`Answer with a JSON object matching this JSON Schema: ${JSON.stringify(schema)}`);
    }
    const parts: ContentPart[] = [{ type: 'text', text: lines.join('\n') }];
    if (this.wantsFrame && context.frame !== undefined) {
      parts.push({ type: 'image_url', image_url: { url: context.frame } });
    }
    if (this.#sendMapImage) {
      const url = gridImageDataUrl(context.grid, {
        pose: context.pose,
        goal: context.goal,
        size: 200,
      });
      parts.push({ type: 'text', text: 'The map (north up; black: obstacle, grey: unknown):' });
      parts.push({ type: 'image_url', image_url: { url } });
    }
    return parts;
  }

  async #request(
    messages: ChatMessage[],
    schema: Record<string, unknown>,
    signal: AbortSignal,
  ): Promise<string> {
    const body: Record<string, unknown> = {
      model: this.#model,
      messages,
      temperature: this.#temperature,
      max_tokens: this.#maxTokens,
    };
    if (this.#format === 'json_schema') {
      body['response_format'] = {
        type: 'json_schema',
        json_schema: { name: 'navigation_decision', schema, strict: true },
      };
    } else if (this.#format === 'json_object') {
      body['response_format'] = { type: 'json_object' };
    }
    const headers: Record<string, string> = { 'content-type': 'application/json' };
    if (this.#apiKey !== undefined && this.#apiKey !== '')
      headers['authorization'] = `Bearer ${this.#apiKey}`;
    const timeout = AbortSignal.timeout(this.#timeoutMs);
    let response: Response;
    let text: string;
    try {
      response = await this.#fetch(this.#url, {
        method: 'POST',
        headers,
        body: JSON.stringify(body),
        signal: AbortSignal.any([signal, timeout]),
      });
      text = await response.text();
    } catch (error) {
      if (signal.aborted) throw error;
      if (timeout.aborted) {
        throw new AttemptError(`no reply within ${this.#timeoutMs} ms`, true);
      }
      throw new AttemptError(
        `request failed: ${error instanceof Error ? error.message : String(error)}`,
        true,
      );
    }
    if (!response.ok) {
      const snippet = text.slice(0, 200);
      if (response.status === 400 && this.#format === 'json_schema') {
        // Many servers do not support structured output: ask for plain JSON instead.
        this.#format = 'json_object';
        this.#logger.warn('server refused json_schema; using json_object', {
          status: response.status,
        });
        throw new AttemptError(`HTTP 400 with json_schema (${snippet})`, true);
      }
      const retryable =
        response.status === 408 || response.status === 429 || response.status >= 500;
      throw new AttemptError(`HTTP ${response.status}: ${snippet}`, retryable);
    }
    let payload: unknown;
    try {
      payload = JSON.parse(text);
    } catch {
      throw new AttemptError('the server answered with something that is not JSON', true);
    }
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

  #aborted(signal: AbortSignal): NavigationError {
    return new NavigationError('ABORTED', `${this.name}: decision cancelled`, {
      cause: signal.reason,
    });
  }
}
