import { z } from 'zod';
import { HalErrorCodeSchema, toHalError } from './errors.js';
import type { HalErrorCode, HalErrorDetails } from './errors.js';
import { HALModeSchema } from './mode.js';
import type { HALMode } from './mode.js';

/**
 * The outcome of a HAL call. `success` says whether it did what was asked; on failure `error` is a
 * human-readable message and `code` the machine-readable reason. `mode` says which world ran it.
 */
export interface HALToolResult {
  /** True when the call did what was asked (a motion: it finished). */
  success: boolean;
  /** What the call produced (pose after a motion, steps executed, ...). */
  data?: Record<string, unknown>;
  /** Human-readable reason for a failure, naming the parameter and the limit where one applies. */
  error?: string;
  /** Machine-readable reason for a failure. */
  code?: HalErrorCode;
  /** Structured facts about a failure (parameter, limit, received value, robot's own reply). */
  details?: HalErrorDetails;
  /** When the call finished, in milliseconds since the Unix epoch (or the simulated clock). */
  timestamp: number;
  /** Which world ran the call. */
  mode: HALMode;
  /** How long the call took, in milliseconds. */
  executionTime?: number;
}

export const HALToolResultSchema = z
  .object({
    success: z.boolean().describe('True when the call did what was asked'),
    data: z.record(z.string(), z.unknown()).optional().describe('What the call produced'),
    error: z.string().optional().describe('Human-readable failure reason'),
    code: HalErrorCodeSchema.optional(),
    details: z.record(z.string(), z.unknown()).optional().describe('Structured failure facts'),
    timestamp: z
      .number()
      .describe('Completion time, ms since the Unix epoch or the simulated clock'),
    mode: HALModeSchema,
    executionTime: z.number().nonnegative().optional().describe('Duration of the call, ms'),
  })
  .refine((r) => r.success || (r.error !== undefined && r.code !== undefined), {
    message: 'a failed result carries both "error" and "code"',
  })
  .describe('Outcome of a HAL call');

/** Builds a successful result. */
export function successResult(
  mode: HALMode,
  timestamp: number,
  data?: Record<string, unknown>,
  executionTime?: number,
): HALToolResult {
  const result: HALToolResult = { success: true, timestamp, mode };
  if (data !== undefined) result.data = data;
  if (executionTime !== undefined) result.executionTime = executionTime;
  return result;
}

/** Builds a failed result from anything thrown (a HalError keeps its code and details). */
export function failureResult(
  mode: HALMode,
  timestamp: number,
  thrown: unknown,
  executionTime?: number,
): HALToolResult {
  const error = toHalError(thrown);
  const result: HALToolResult = {
    success: false,
    error: error.message,
    code: error.code,
    timestamp,
    mode,
  };
  if (error.details !== undefined) result.details = error.details;
  if (executionTime !== undefined) result.executionTime = executionTime;
  return result;
}
