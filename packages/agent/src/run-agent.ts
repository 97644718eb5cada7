import { createToolExecutor, toOpenAITools } from '@hal/tools';
import { agentLoop } from './agent-loop.js';
import type { AgentOutcome } from './agent-loop.js';
import { AgentError } from './errors.js';
import { resolveSettings } from './options.js';
import type { AgentToolExecutor, RunAgentOptions } from './options.js';
import { AGENT_SYSTEM_PROMPT } from './prompt.js';

/**
 * Runs a goal on a robot through an OpenAI-compatible chat-completions endpoint: the model gets
 * the HAL's tools (OpenAI `tools`), each tool call it makes runs on the HAL through the executor
 * and its result goes back (camera frames as images), until the model answers without a tool
 * call or a cap, the signal or an endpoint failure ends the run. Resolves with the outcome (it
 * does not reject for a failing endpoint: that is `reason: 'error'`); rejects with an AgentError
 * CONFIG only for bad options.
 */
export async function runAgent(options: RunAgentOptions): Promise<AgentOutcome> {
  const settings = resolveSettings(options);
  const executor = toolExecutor(options);
  return agentLoop(settings, {
    executor,
    chatTools: toOpenAITools(executor.tools),
    systemPrompt: options.systemPrompt ?? AGENT_SYSTEM_PROMPT,
    signal: options.signal,
    onEvent: options.onEvent,
  });
}

function toolExecutor(options: RunAgentOptions): AgentToolExecutor {
  if (options.executor !== undefined) return options.executor;
  if (options.hal === undefined)
    throw new AgentError('CONFIG', 'give "hal" or "executor": the agent needs a robot to drive');
  return createToolExecutor(options.hal, {
    ...(options.leash === undefined ? {} : { leash: options.leash }),
    ...(options.toolTimeoutMs === undefined ? {} : { timeoutMs: options.toolTimeoutMs }),
  });
}
