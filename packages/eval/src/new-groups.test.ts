import { castRay, solidsOf } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import type { EvalAgent } from './agent.js';
import { oracleAgent } from './agents/oracle.js';
import { builtinTasks } from './builtin-tasks.js';
import { trueAnswer } from './checks.js';
import { runEval } from './run-eval.js';
import type { Check, Task } from './task-schema.js';
import { objectSolids } from './truth.js';
import { realiseTask } from './variant.js';

// The search, memory and sequences groups: a memory question's answer changes with the seed (no
// fixed answer passes), and a sequence is judged in its order: the oracle driving the same stops
// in another order, or leaving one out, fails.

type Visit = Extract<Check, { kind: 'visit-in-order' }>;

/** The oracle on the task with its visit-in-order stops changed by `change`. */
function reordered(name: string, change: (stops: Visit['stops']) => Visit['stops']): EvalAgent {
  const oracle = oracleAgent();
  return {
    name,
    usesGroundTruth: true,
    run: async (trial) => {
      const truth = trial.truth;
      if (truth === undefined) return { answer: 'no truth' };
      const checks = truth.task.checks.map((c) =>
        c.kind === 'visit-in-order' ? { ...c, stops: change(c.stops) } : c,
      );
      return oracle.run({ ...trial, truth: { ...truth, task: { ...truth.task, checks } } });
    },
  };
}

const stopsOf = (task: Task) =>
  task.checks.find((c): c is Visit => c.kind === 'visit-in-order')?.stops ?? [];

describe('the memory tasks', () => {
  it('change the true answer of every question from seed to seed', () => {
    for (const task of builtinTasks(['memory'])) {
      const check = task.checks.find((c) => c.kind === 'answer');
      if (check?.kind !== 'answer') throw new Error(`${task.id} asks nothing`);
      const answers = new Set(
        Array.from({ length: 30 }, (_, i) =>
          trueAnswer(realiseTask(task, i + 1), check.question, check),
        ),
      );
      expect([task.id, answers.size >= 2]).toEqual([task.id, true]);
      expect([task.id, answers.has('none')]).toEqual([task.id, false]);
    }
  });

  it('also ask the robot to end somewhere else (the answer is from memory)', () => {
    for (const task of builtinTasks(['memory']))
      expect([task.id, task.checks.some((c) => c.kind === 'reach-point')]).toEqual([task.id, true]);
  });
});

describe('the sequences tasks', () => {
  const sequences = builtinTasks(['sequences']);

  it('every one visits its stops in order, and the oracle passes them', async () => {
    expect(sequences.length).toBeGreaterThanOrEqual(8);
    const report = await runEval({ tasks: sequences, agents: [oracleAgent()], trials: 2, seed: 3 });
    expect(report.scores.agents[0]?.overall.rate).toBe(1);
  }, 60_000);

  it('fail the same stops driven in reverse order, or with the last one left out', async () => {
    const multi = sequences.filter((t) => stopsOf(t).length >= 2);
    expect(multi.length).toBeGreaterThanOrEqual(6);
    const report = await runEval({
      tasks: multi,
      agents: [
        reordered('reverse', (stops) => [...stops].reverse()),
        reordered('skip-last', (stops) => stops.slice(0, -1)),
      ],
      trials: 2,
      seed: 3,
    });
    for (const agent of report.scores.agents) {
      expect([agent.agent, agent.overall.successes]).toEqual([agent.agent, 0]);
      for (const trial of agent.trials)
        expect(trial.failures.join('; ')).toMatch(/^visit-in-order: visited \d of the \d stops/);
    }
  }, 60_000);
});

describe('the search tasks', () => {
  it("put the named object out of the camera's view at the start (outside ±31°, beyond 2.5 m or behind something)", () => {
    for (const task of builtinTasks(['search'])) {
      const check = task.checks.find((c) => c.kind === 'reach-object');
      if (check?.kind !== 'reach-object') throw new Error(`${task.id} reaches no object`);
      for (let seed = 1; seed <= 20; seed += 1) {
        const v = realiseTask(task, seed);
        const o = v.objects.find((x) => x.name === check.object);
        if (o === undefined) throw new Error(`${task.id} has no ${check.object}`);
        const bearing = Math.atan2(o.y - v.start.y, o.x - v.start.x) - v.start.yaw;
        const off = Math.abs(Math.atan2(Math.sin(bearing), Math.cos(bearing)));
        const far = Math.hypot(o.x - v.start.x, o.y - v.start.y) > 2.5;
        // something else (a wall, an obstacle, another object) is first on the line to it
        const solids = solidsOf(v.map);
        const own = objectSolids(v)[v.objects.indexOf(o)];
        const line = Math.atan2(o.y - v.start.y, o.x - v.start.x);
        const hidden = castRay(v.start.x, v.start.y, line, 100, solids).solid !== own;
        expect([task.id, seed, off > (31 * Math.PI) / 180 || far || hidden]).toEqual([
          task.id,
          seed,
          true,
        ]);
      }
    }
  });
});
