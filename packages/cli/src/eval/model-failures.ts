// What `hal eval` says of an agent whose model could not be used (it never answered: an endpoint
// out of reach, a key refused, a local model whose grammar could not be built): a failed run,
// with the cause named once per agent, never a score of 0 %.
import type { EvalReport, TrialScore } from '@hal/eval';
import { modelFailureNote } from '@hal/eval';
import { CliError } from '../cli-error.js';

/** The verdict of one trial for the progress line: pass, FAIL (the first check), or the model's. */
export function trialVerdict(score: TrialScore): string {
  if (score.modelFailure !== null) return `model failed (${score.modelFailure.code})`;
  return score.success ? 'pass' : `FAIL (${score.failures[0] ?? ''})`;
}

/**
 * A FAILED error naming each agent whose model failed, with its first cause; undefined when every
 * model answered. The run is then no measure of those agents: `hal eval` exits 1.
 */
export function modelFailureError(report: EvalReport): CliError | undefined {
  const failed = report.scores.agents.flatMap((a) =>
    a.modelFailure === null
      ? []
      : [
          `${a.agent}: ${modelFailureNote(a.modelFailure)}: ${a.modelFailure.code}: ${a.modelFailure.message}`,
        ],
  );
  if (failed.length === 0) return undefined;
  return new CliError(
    'FAILED',
    `the model could not be used, so its trials are not scored: ${failed.join('; ')}`,
  );
}
