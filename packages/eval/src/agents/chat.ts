import { runAgent } from '@hal/agent';
import type { AgentEndpoint, ChatProvider } from '@hal/agent';
import type { HalTool } from '@hal/tools';
import type { EvalAgent } from '../agent.js';

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
  /** Runs before each trial with the tools it offers (a local model builds its grammar here). */
  prepare?: (tools: HalTool[]) => Promise<void>;
}

/**
 * An agent that is a model: each trial runs `runAgent` with the trial's tools (leash, faults and
 * budget included), counting the tokens and the model's time from the loop's `usage` events.
 */
export function chatAgent(options: ChatAgentOptions): EvalAgent {
  return {
    name: options.name,
    run: async (trial) => {
      await options.prepare?.(trial.tools);
      let tokensIn = 0;
      let tokensOut = 0;
      let modelMs = 0;
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
          if (event.type !== 'usage') return;
          tokensIn += event.promptTokens ?? 0;
          tokensOut += event.completionTokens ?? 0;
          modelMs += event.durationMs;
        },
      });
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
      };
    },
  };
}
