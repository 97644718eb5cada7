import { errorResult, REFUSAL_CODES } from '@hal/tools';
import type { ToolResult } from '@hal/tools';
import type { HALToolResult } from '@hal/types';

/**
 * How a skill ended, in one word a small model can branch on. `refused`, `estopped` and
 * `failed` are errors (the result's `isError`, with the code that says why); the others are
 * answers: not finding a thing, or being blocked, is what happened, not a fault.
 */
export type SkillOutcome =
  | 'done'
  | 'reached'
  | 'found'
  | 'not-found'
  | 'blocked'
  | 'refused'
  | 'guard-stopped'
  | 'estopped'
  | 'failed';

/** The believed pose a skill reports: odometry, metres and degrees (counter-clockwise from +x). */
export interface SkillPose {
  x: number;
  y: number;
  yawDeg: number;
}

const ERRORS: ReadonlySet<SkillOutcome> = new Set(['refused', 'estopped', 'failed']);

/** A skill's answer: one sentence for the model, the facts for an app. */
export function skillResult(
  outcome: SkillOutcome,
  text: string,
  facts: Record<string, unknown> = {},
  code?: string,
): ToolResult {
  const isError = ERRORS.has(outcome);
  return {
    isError,
    ...(code === undefined ? {} : { code }),
    content: [{ type: 'text', text }],
    structured: { outcome, ...(code === undefined ? {} : { code }), ...facts, message: text },
  };
}

/** A skill a stop interrupted, between two of its motions. */
export function interruptedResult(skill: string, facts: Record<string, unknown>): ToolResult {
  return skillResult(
    'failed',
    `Stopped: a stop interrupted ${skill}; it started no motion after it.`,
    facts,
    'INTERRUPTED',
  );
}

/** A skill's refusal of its arguments, before anything moved. */
export function badArguments(skill: string, message: string): ToolResult {
  return errorResult('INVALID_PARAMETER', `${skill}: ${message}`);
}

/** What a failed motion's result means for a skill, and the words for it. */
export interface MotionFailure {
  outcome: SkillOutcome;
  code: string;
  /** Why, in words: "the leash allows at most 0.5 m per call". */
  why: string;
}

/** The outcome a failed HAL motion result stands for. */
export function motionFailure(result: HALToolResult): MotionFailure {
  // a refusal by the executor (the leash) carries its code in the details (see toolBackedHal)
  const own = result.details?.['code'];
  const code = result.code ?? (typeof own === 'string' ? own : 'HARDWARE_ERROR');
  const why = result.error ?? code;
  if (code === 'EMERGENCY_STOPPED')
    return { outcome: 'estopped', code, why: 'the emergency stop is engaged' };
  if (code === 'OBSTACLE_AHEAD') return { outcome: 'guard-stopped', code, why };
  if (code === 'COLLISION') return { outcome: 'blocked', code, why };
  if (REFUSAL_CODES.has(code)) return { outcome: 'refused', code, why };
  return { outcome: 'failed', code, why };
}

/** Metres with two decimals, as the words say them. */
export const m2 = (v: number): string => v.toFixed(2);
/** Whole degrees. */
export const deg0 = (v: number): string => Math.round(v).toString();
