import { errorMessage, withTimeout } from '@hal/types';
import type { DecisionContext } from '../decision/provider.js';
import { parseDecision } from '../decision/schema.js';
import type { NavigationDecision } from '../decision/schema.js';
import { NavigationError } from '../errors.js';
import type { BridgeContext } from './bridge-context.js';
import { failed, stopRequested } from './navigation-outcome.js';
import type { Terminal } from './navigation-outcome.js';

/**
 * Asks the provider for a decision, bounded by `decisionTimeoutMs` (its signal aborts when the run
 * stops or the time runs out), and checks it against the decision schema before anything moves
 * (safety layer 1). No decision, or an invalid one, ends the run.
 */
export async function askProvider(
  ctx: BridgeContext,
  context: DecisionContext,
  runSignal: AbortSignal,
): Promise<{ decision: NavigationDecision } | { terminal: Terminal }> {
  const { provider } = ctx;
  const { decisionTimeoutMs } = ctx.settings;
  const timeout = new AbortController();
  const signal = AbortSignal.any([runSignal, timeout.signal]);
  // A stop() during the wait explains the missing decision; otherwise the provider failed.
  const noDecision = (why: string): { terminal: Terminal } => ({
    terminal: ctx.stopRequested
      ? stopRequested()
      : failed('PROVIDER_ERROR', `${provider.name} gave no decision${why}`),
  });
  let answer: { value: NavigationDecision } | undefined;
  try {
    answer = await withTimeout(provider.decide(context, signal), decisionTimeoutMs);
  } catch (error) {
    return noDecision(`: ${errorMessage(error)}`);
  }
  if (answer === undefined) {
    timeout.abort(new NavigationError('TIMEOUT', 'decision timed out'));
    return noDecision(` within ${decisionTimeoutMs} ms`);
  }
  const parsed = parseDecision(answer.value);
  if (!parsed.ok) {
    return {
      terminal: failed(
        'INVALID_DECISION',
        `${provider.name} gave an invalid decision: ${parsed.problem}`,
      ),
    };
  }
  return { decision: parsed.decision };
}
