import type { HALToolResult } from '@hal/types';

/** A straight motion split into legs: how much is left, and how to drive one leg. */
export interface LegPlan {
  /** How far the motion still has to go, metres. */
  remainingM(): Promise<number>;
  /** Drives one leg of `legM` metres; `final`: the rest of the motion, exactly as asked. */
  run(legM: number, final: boolean): Promise<HALToolResult>;
}

const SUMMED = ['leftSteps', 'rightSteps', 'moves'] as const;

/**
 * One result for a motion driven in legs: the last leg's, with the step counts summed over the
 * legs, their time added and `legs` their number. A motion of one leg answers its own result.
 */
export function combineLegs(results: readonly HALToolResult[]): HALToolResult | undefined {
  const last = results[results.length - 1];
  if (last === undefined || results.length === 1) return last;
  const data: Record<string, unknown> = { ...last.data, legs: results.length };
  for (const key of SUMMED) {
    const values = results.map((r) => r.data?.[key]);
    if (values.every((v): v is number => typeof v === 'number')) {
      data[key] = values.reduce((a, b) => a + b, 0);
    }
  }
  const combined: HALToolResult = { ...last, data };
  const times = results.map((r) => r.executionTime);
  if (times.every((t): t is number => typeof t === 'number')) {
    combined.executionTime = times.reduce((a, b) => a + b, 0);
  }
  return combined;
}
