import type { AgentError } from './errors.js';

/** Why a run ended. */
export type AgentDoneReason =
  /** The model answered without calling a tool: it says the goal is done (or cannot be). */
  | 'completed'
  /** The model refused the goal (the chat-completions `refusal` field). */
  | 'refused'
  /** `caps.maxSteps` model requests were made and the model still wanted tools. */
  | 'max_steps'
  /** `caps.maxMs` passed. */
  | 'max_ms'
  /** The caller's AbortSignal fired. */
  | 'aborted'
  /** The endpoint failed for good (a non-retryable HTTP error, or the retries ran out). */
  | 'error';

/** What a run reports as it goes, for a UI or a log. `step` counts model requests from 1. */
export type AgentEvent =
  | { type: 'step_started'; step: number; elapsedMs: number }
  | { type: 'assistant_text'; step: number; text: string }
  /** A piece of the model's reply as it is generated (providers that stream). */
  | { type: 'token'; step: number; text: string }
  /** One model request finished: how long it took and, when known, its token counts. */
  | {
      type: 'usage';
      step: number;
      durationMs: number;
      promptTokens?: number;
      completionTokens?: number;
      /** completionTokens over durationMs, per second. */
      tokensPerSecond?: number;
    }
  /** Older turns were left out of the request to fit the model's context window. */
  | {
      type: 'context_trimmed';
      step: number;
      droppedMessages: number;
      promptTokens: number;
      contextTokens: number;
    }
  | { type: 'tool_call'; step: number; id: string; name: string; arguments: string }
  | {
      type: 'tool_result';
      step: number;
      id: string;
      name: string;
      isError: boolean;
      /** The executor's code for an error (UNKNOWN_TOOL, BAD_ARGUMENTS, a HAL error code...). */
      code?: string;
      /** The text the model receives. */
      text: string;
      /** Whether a camera frame went back to the model with it. */
      image: boolean;
      durationMs: number;
    }
  | {
      type: 'retry';
      step: number;
      /** The attempt that failed, from 1. */
      attempt: number;
      /** How long the loop waits before the next attempt. */
      delayMs: number;
      reason: string;
      status?: number;
    }
  | { type: 'error'; step: number; error: AgentError }
  | { type: 'done'; reason: AgentDoneReason; steps: number; elapsedMs: number; text?: string };

/** Receives a run's events; an exception it throws is logged and otherwise ignored. */
export type AgentEventListener = (event: AgentEvent) => void;
