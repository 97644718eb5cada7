import { runAgent } from '@hal/agent';
import type { AgentEndpoint, AgentError, ChatProvider } from '@hal/agent';
import type { ToolProfile } from '@hal/skills';
import type { AgentTool } from '@hal/tools';
import { errorMessage } from '@hal/types';
import type { EvalAgent, ModelFailure } from '../agent.js';

/** Options of {@link chatAgent}: a model behind `@hal/agent`'s loop. */
export interface ChatAgentOptions {
  /** The name in reports, e.g. `openai:gpt-4o-mini`. */
  name: string;
  /** An OpenAI-compatible endpoint; or give `provider`. */
  endpoint?: AgentEndpoint;
  /** Any ChatProvider, e.g. `createLocalChatProvider()` of `@hal/agent-local`. */
  provider?: ChatProvider;
  /** Replaces the agent's built-in system prompt. */
  systemPrompt?: string;
  /** With `endpoint`: sampling temperature. */
  temperature?: number;
  /** Most model requests per trial. Default: the task's tool-call budget. */
  maxSteps?: number;
  /** The tools it is offered unless the run names a profile. Default `primitives`. */
  toolProfile?: ToolProfile;
  /**
   * Runs before each trial with the tools it offers (a local model builds its grammar here). A
   * rejection is a model failure: the trial is not scored.
   */
  prepare?: (tools: AgentTool[]) => Promise<void>;
}

/** A failure's own code: a provider's (a local model's SCHEMA_UNSUPPORTED), else the loop's. */
function failureOf(error: AgentError): ModelFailure {
  const own = error.details?.['code'];
  return { code: typeof own === 'string' ? own : error.code, message: error.message };
}

/** The message and code of anything thrown. */
function thrownFailure(error: unknown): ModelFailure {
  const code = (error as { code?: unknown } | null)?.code;
  return {
    code: typeof code === 'string' ? code : 'PREPARE',
    message: errorMessage(error),
  };
}

/**
 * An agent that is a model: each trial runs `runAgent` with the trial's tools (leash, faults and
 * budget included), counting the tokens and the model's time from the loop's `usage` events.
 * A trial in which the model never answered (its endpoint failed for good, or the trial's time ran
 * out while its requests were being retried, or `prepare` failed) ends with a `modelFailure`,
 * not a score: the model could not be reached, which says nothing of how it does the task.
 */
export function chatAgent(options: ChatAgentOptions): EvalAgent {
  return {
    name: options.name,
    ...(options.toolProfile === undefined ? {} : { toolProfile: options.toolProfile }),
    run: async (trial) => {
      try {
        await options.prepare?.(trial.tools);
      } catch (error) {
        return { answer: '', modelFailure: thrownFailure(error) };
      }
      let tokensIn = 0;
      let tokensOut = 0;
      let modelMs = 0;
      // whether the model answered at all: a reply (usage) or a streamed token
      let answered = false;
      let lastRetry: string | undefined;
      const outcome = await runAgent({
        goal: trial.instruction,
        executor: { tools: trial.tools, execute: trial.execute },
        ...(options.endpoint === undefined ? {} : { endpoint: options.endpoint }),
        ...(options.provider === undefined ? {} : { provider: options.provider }),
        ...(options.systemPrompt === undefined ? {} : { systemPrompt: options.systemPrompt }),
        ...(options.temperature === undefined ? {} : { temperature: options.temperature }),
        caps: { maxSteps: options.maxSteps ?? trial.maxToolCalls },
        signal: trial.signal,
        onEvent: (event) => {
          if (event.type === 'token') answered = true;
          if (event.type === 'retry') lastRetry = event.reason;
          if (event.type !== 'usage') return;
          answered = true;
          tokensIn += event.promptTokens ?? 0;
          tokensOut += event.completionTokens ?? 0;
          modelMs += event.durationMs;
        },
      });
      let modelFailure: ModelFailure | undefined;
      if (!answered && outcome.reason === 'error' && outcome.error !== undefined)
        modelFailure = failureOf(outcome.error);
      else if (!answered && lastRetry !== undefined && outcome.reason !== 'completed')
        modelFailure = {
          code: 'NO_ANSWER',
          message: `no answer before the trial's time ran out, its requests still being retried (the last failed: ${lastRetry})`,
        };
      return {
        answer: outcome.text,
        tokensIn,
        tokensOut,
        modelMs,
        ...(outcome.reason === 'completed'
          ? {}
          : {
              stopped: `${outcome.reason}${outcome.error === undefined ? '' : `: ${outcome.error.message}`}`,
            }),
        ...(modelFailure === undefined ? {} : { modelFailure }),
      };
    },
  };
}
