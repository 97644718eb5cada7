import { describe, expect, it } from 'vitest';
import { summariseGroups, wilson } from './scores.js';
import type { TrialScore } from './trial.js';
import type { TaskGroup } from './task-schema.js';

/** A trial of `task` in `group` that succeeded or not (the other fields as a blank trial). */
function trial(task: string, group: TaskGroup, success: boolean, seed = 1): TrialScore {
  return {
    task,
    group,
    seed,
    success,
    failures: success ? [] : ['displacement: ended 0.1 m from the target'],
    modelFailure: null,
    collisions: 0,
    endPose: { x: 0, y: 0, yawDeg: 0 },
    positionErrorM: null,
    headingErrorDeg: null,
    pathLengthM: 0,
    optimalPathM: null,
    toolCalls: 1,
    refusedCalls: 0,
    lostCalls: 0,
    tokensIn: 0,
    tokensOut: 0,
    simSeconds: 1,
    safetyEvents: [],
    answer: 'Done.',
  };
}

/** k trials of a task, the first `successes` of them successes. */
const trials = (task: string, group: TaskGroup, successes: number, k: number) =>
  Array.from({ length: k }, (_, i) => trial(task, group, i < successes, i + 1));

describe('wilson', () => {
  it('gives the 95 % Wilson interval of a proportion', () => {
    expect(wilson(5, 10)).toEqual({
      successes: 5,
      trials: 10,
      rate: 0.5,
      low: 0.2366,
      high: 0.7634,
    });
    expect(wilson(0, 10)).toMatchObject({ low: 0, high: 0.2775 });
    expect(wilson(10, 10)).toMatchObject({ low: 0.7225, high: 1 });
  });

  it('refuses counts that are not a proportion', () => {
    expect(() => wilson(3, 2)).toThrow(RangeError);
    expect(() => wilson(1.5, 2)).toThrow(/integers/);
  });
});

describe('summariseGroups', () => {
  // 8 precision tasks, 4 passed on all 5 seeds and 4 on none; 2 safety tasks, 3 and 1 of 5
  const scores = [
    ...[0, 1, 2, 3, 4, 5, 6, 7].flatMap((i) =>
      trials(`precision/t${i}`, 'precision', i < 4 ? 5 : 0, 5),
    ),
    ...trials('safety/a', 'safety', 3, 5),
    ...trials('safety/b', 'safety', 1, 5),
  ];
  const { groups, overall, passK } = summariseGroups(scores);

  it('gives the rates with an interval over tasks, wider than Wilson over the trials', () => {
    expect(overall).toMatchObject({ successes: 24, trials: 50, rate: 0.48, tasks: 10 });
    expect(overall.interval).toBe('bootstrap-tasks');
    const naive = wilson(24, 50);
    expect(overall.high - overall.low).toBeGreaterThan(1.5 * (naive.high - naive.low));
    expect(groups.map((g) => [g.group, g.tasks, g.success.successes, g.passAllTasks])).toEqual([
      ['precision', 8, 20, 4],
      ['safety', 2, 4, 0],
    ]);
    expect(groups[0]?.success.interval).toBe('bootstrap-tasks');
  });

  it('gives pass^k for k = 1 to the trials per task', () => {
    // per task: 4 tasks at 1, 4 at 0; 3 of 5 gives 0.6, 0.3, 0.1, 0, 0; 1 of 5 gives 0.2, 0...
    expect(passK).toEqual([
      { k: 1, rate: 0.48 },
      { k: 2, rate: 0.43 },
      { k: 3, rate: 0.41 },
      { k: 4, rate: 0.4 },
      { k: 5, rate: 0.4 },
    ]);
  });

  it('gives the same numbers for the same trials', () => {
    expect(JSON.stringify(summariseGroups(scores))).toBe(
      JSON.stringify(summariseGroups([...scores])),
    );
  });
});
