import { GoalSeekingProvider, NavigationBridge } from '@hal/navigation';
import type { DecisionProvider } from '@hal/navigation';
import type { EvalAgent } from '../agent.js';
import { targetOf } from '../checks.js';
import { approachObject } from '../route.js';

/** Options of {@link navigationAgent}. */
export interface NavigationAgentOptions {
  /** The name in reports. Default `nav:` + the provider's name. */
  name?: string;
  /** Who decides each cycle. Default the deterministic GoalSeekingProvider. */
  provider?: DecisionProvider;
  /** Seed the bridge's world model with the task's map. Default true. */
  knownMap?: boolean;
}

/**
 * The navigation bridge of `@hal/navigation` as an agent: it is given the task's goal point (a
 * bridge takes a point, not words: the point comes from the task's check) and drives there with
 * its decision provider, through the trial's tools (leash, faults and budget apply). Tasks with
 * no place to reach (questions, e-stops, stopping before a wall) it cannot do, and says so.
 */
export function navigationAgent(options: NavigationAgentOptions = {}): EvalAgent {
  const provider = () => options.provider ?? new GoalSeekingProvider();
  return {
    name: options.name ?? `nav:${provider().name}`,
    usesGroundTruth: true,
    run: async (trial) => {
      const truth = trial.truth;
      if (truth === undefined) return { answer: 'no goal given', stopped: 'no goal' };
      let goal: { x: number; y: number } | undefined;
      for (const check of truth.task.checks) {
        if (check.kind === 'reach-object') {
          const object = truth.objects.find((o) => o.name === check.object);
          if (object !== undefined)
            goal = approachObject(truth.map, truth.start, object, check.withinM)?.point;
        } else {
          goal = targetOf(check, truth);
        }
        if (goal !== undefined) break;
      }
      if (goal === undefined)
        return { answer: 'This task has no place to drive to.', stopped: 'no goal point' };
      const bridge = new NavigationBridge({
        hal: trial.hal,
        provider: provider(),
        ...(options.knownMap === false ? {} : { map: truth.map }),
        goalToleranceM: 0.02,
      });
      const outcome = await bridge.run(goal, { signal: trial.signal });
      return {
        answer: outcome.message,
        ...(outcome.status === 'reached' ? {} : { stopped: outcome.reason }),
      };
    },
  };
}
