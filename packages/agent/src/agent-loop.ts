import { errorMessage } from '@hal/types';
import type { ToolResult } from '@hal/tools';
import type { ChatContentPart, ChatMessage, ChatTool, ChatToolCall } from './chat-types.js';
import { AgentError } from './errors.js';
import type { AgentDoneReason, AgentEvent, AgentEventListener } from './events.js';
import type { AgentSettings, AgentToolExecutor } from './options.js';
import { imagesMessage, resultImages, resultText } from './tool-turn.js';

/** How a run ended. */
export interface AgentOutcome {
  reason: AgentDoneReason;
  /** Model requests made. */
  steps: number;
  /** The model's last text (its summary when it completed, the refusal when it refused). */
  text: string;
  elapsedMs: number;
  /** The endpoint's failure, when `reason` is 'error'. */
  error?: AgentError;
  /** The whole conversation, system prompt first. */
  messages: ChatMessage[];
}

/** What the loop needs beyond the settings. */
export interface LoopParts {
  executor: AgentToolExecutor;
  chatTools: ChatTool[];
  systemPrompt: string;
  signal: AbortSignal | undefined;
  onEvent: AgentEventListener | undefined;
}

const STOPPED = Symbol('stopped');

/** How long the run waits for the stop it runs at its end (a custom executor might hang). */
const STOP_TIMEOUT_MS = 10_000;

/** Resolves with the promise's value, or STOPPED as soon as `signal` aborts. */
function unlessStopped<T>(promise: Promise<T>, signal: AbortSignal): Promise<T | typeof STOPPED> {
  if (signal.aborted) return Promise.resolve(STOPPED);
  return new Promise((resolve, reject) => {
    const stop = () => resolve(STOPPED);
    signal.addEventListener('abort', stop, { once: true });
    promise.then(
      (value) => {
        signal.removeEventListener('abort', stop);
        resolve(value);
      },
      (error: unknown) => {
        signal.removeEventListener('abort', stop);
        reject(error instanceof Error ? error : new Error(String(error)));
      },
    );
  });
}

/**
 * The loop: ask the model, run its tool calls, give it the results, until it answers without a
 * tool call, refuses, or a cap, the caller's signal or an endpoint failure ends the run. Any end
 * other than 'completed' runs the executor's stop tool, so no motion outlives the run.
 */
export async function agentLoop(settings: AgentSettings, parts: LoopParts): Promise<AgentOutcome> {
  const started = Date.now();
  const { executor, chatTools, onEvent } = parts;
  const deadline = AbortSignal.timeout(settings.caps.maxMs);
  const run = AbortSignal.any(parts.signal === undefined ? [deadline] : [parts.signal, deadline]);
  const messages: ChatMessage[] = [
    { role: 'system', content: parts.systemPrompt },
    { role: 'user', content: settings.goal },
  ];
  const elapsed = () => Date.now() - started;
  const emit = (event: AgentEvent) => {
    try {
      onEvent?.(event);
    } catch (error) {
      settings.logger.warn('agent event listener threw', { error: errorMessage(error) });
    }
  };
  let step = 0;
  let text = '';

  const stopTool =
    executor.tools.find((t) => t.safety === 'stop') ??
    executor.tools.find((t) => t.name === 'stop');
  const finish = async (reason: AgentDoneReason, error?: AgentError): Promise<AgentOutcome> => {
    if (reason !== 'completed' && stopTool !== undefined) {
      const id = `stop_${step}`;
      emit({ type: 'tool_call', step, id, name: stopTool.name, arguments: '{}' });
      const t0 = Date.now();
      try {
        const result = await unlessStopped(
          executor.execute({ id, name: stopTool.name, arguments: {} }),
          AbortSignal.timeout(STOP_TIMEOUT_MS),
        );
        if (result === STOPPED)
          settings.logger.error('the stop tool did not answer in time', { ms: STOP_TIMEOUT_MS });
        else emit(resultEvent(step, id, stopTool.name, result, Date.now() - t0));
      } catch (cause) {
        // The executors of @hal/tools never throw; one of the caller's own might.
        settings.logger.error('the stop tool threw', { error: errorMessage(cause) });
      }
    }
    const elapsedMs = elapsed();
    emit({ type: 'done', reason, steps: step, elapsedMs, ...(text === '' ? {} : { text }) });
    return {
      reason,
      steps: step,
      text,
      elapsedMs,
      ...(error === undefined ? {} : { error }),
      messages,
    };
  };
  const stoppedReason = (): AgentDoneReason =>
    parts.signal?.aborted === true ? 'aborted' : 'max_ms';

  for (;;) {
    if (run.aborted) return finish(stoppedReason());
    if (step >= settings.caps.maxSteps) return finish('max_steps');
    step += 1;
    emit({ type: 'step_started', step, elapsedMs: elapsed() });
    let reply;
    const requested = Date.now();
    try {
      reply = await settings.provider.complete(
        { messages, tools: chatTools },
        {
          step,
          signal: run,
          onRetry: (retry) => emit({ type: 'retry', step, ...retry }),
          onToken: (piece) => emit({ type: 'token', step, text: piece }),
          onContextTrimmed: (info) => emit({ type: 'context_trimmed', step, ...info }),
        },
      );
    } catch (cause) {
      if (run.aborted) return finish(stoppedReason());
      const error =
        cause instanceof AgentError ? cause : providerError(settings.provider.name, cause);
      settings.logger.warn('agent request failed', { step, error: error.message });
      emit({ type: 'error', step, error });
      return finish('error', error);
    }
    emit(usageEvent(step, Date.now() - requested, reply.usage));
    if (reply.text !== '') {
      text = reply.text;
      emit({ type: 'assistant_text', step, text: reply.text });
    }
    if (reply.refusal !== undefined && reply.refusal !== '') {
      text = reply.refusal;
      return finish('refused');
    }
    const calls = reply.toolCalls;
    messages.push(
      calls.length === 0
        ? { role: 'assistant', content: reply.text }
        : { role: 'assistant', content: reply.text === '' ? null : reply.text, tool_calls: calls },
    );
    if (calls.length === 0) return finish('completed');
    const images: Array<{ callId: string; name: string; parts: ChatContentPart[] }> = [];
    for (const call of calls) {
      const outcome = await runCall(call);
      if (outcome === STOPPED) return finish(stoppedReason());
    }
    const imageMessage = imagesMessage(images);
    if (imageMessage !== undefined) messages.push(imageMessage);

    async function runCall(call: ChatToolCall): Promise<void | typeof STOPPED> {
      const { name, arguments: args } = call.function;
      emit({ type: 'tool_call', step, id: call.id, name, arguments: args });
      const t0 = Date.now();
      const result = await unlessStopped(
        executor.execute({ id: call.id, name, arguments: args }),
        run,
      );
      if (result === STOPPED) return STOPPED;
      const content = resultText(result);
      messages.push({ role: 'tool', tool_call_id: call.id, content });
      const parts = resultImages(result);
      if (parts.length > 0) images.push({ callId: call.id, name, parts });
      emit(resultEvent(step, call.id, name, result, Date.now() - t0));
      return undefined;
    }
  }
}

function resultEvent(
  step: number,
  id: string,
  name: string,
  result: ToolResult,
  durationMs: number,
): AgentEvent {
  return {
    type: 'tool_result',
    step,
    id,
    name,
    isError: result.isError,
    ...(result.code === undefined ? {} : { code: result.code }),
    text: resultText(result),
    image: result.content.some((part) => part.type === 'image'),
    durationMs,
  };
}

function usageEvent(
  step: number,
  durationMs: number,
  usage: { promptTokens: number; completionTokens: number } | undefined,
): AgentEvent {
  if (usage === undefined) return { type: 'usage', step, durationMs };
  return {
    type: 'usage',
    step,
    durationMs,
    promptTokens: usage.promptTokens,
    completionTokens: usage.completionTokens,
    ...(durationMs > 0 ? { tokensPerSecond: (usage.completionTokens * 1000) / durationMs } : {}),
  };
}

/** A provider's own error as an AgentError PROVIDER, keeping its code in `details`. */
function providerError(provider: string, cause: unknown): AgentError {
  const code = (cause as { code?: unknown } | null)?.code;
  return new AgentError('PROVIDER', `${provider}: ${errorMessage(cause)}`, {
    ...(typeof code === 'string' ? { details: { code } } : {}),
    cause,
  });
}
