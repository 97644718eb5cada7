// A decision provider for the bridge's unit tests that answers from a script. Not exported.
import type { DecisionContext, DecisionProvider } from '../decision/provider.js';
import type { NavigationDecision } from '../decision/schema.js';

/** A provider that answers from a list (the last answer repeats), recording its contexts. */
export class ScriptedProvider implements DecisionProvider {
  readonly name = 'scripted';
  readonly contexts: DecisionContext[] = [];
  readonly #answers: NavigationDecision[];
  constructor(answers: NavigationDecision[]) {
    this.#answers = answers;
  }
  async decide(context: DecisionContext): Promise<NavigationDecision> {
    this.contexts.push(context);
    const answer = this.#answers[Math.min(this.contexts.length - 1, this.#answers.length - 1)];
    if (answer === undefined) throw new Error('no answers scripted');
    return answer;
  }
}

/** A decision with the given action, reasoning 'scripted'. */
export const decision = (
  action: NavigationDecision['action'],
  goal_reached = false,
): NavigationDecision => ({
  reasoning: 'scripted',
  action,
  goal_reached,
});
