import { describe, expect, it } from 'vitest';
import { naiveAgent } from './agents/baselines.js';
import { oracleAgent } from './agents/oracle.js';
import { builtinTasks } from './builtin-tasks.js';
import type { EvalAgent } from './agent.js';
import { navigationAgent } from './agents/navigation.js';
import { RealitySchema, trialReality } from './reality.js';
import type { RealityInput } from './reality.js';
import { runEval } from './run-eval.js';
import type { EvalReport } from './run-eval.js';

describe('trialReality', () => {
  it("runs each knob at the higher of the run's and the task's", () => {
    const task = RealitySchema.parse({ wheelSlipPct: 5, latencyMs: 100 });
    expect(trialReality({ latencyMs: 300, lossRate: 0.2 }, task)).toEqual({
      ...RealitySchema.parse({}),
      wheelSlipPct: 5,
      latencyMs: 300,
      lossRate: 0.2,
    });
    expect(trialReality({ wheelSlipPct: 1 }, task).wheelSlipPct).toBe(5);
    expect(trialReality(undefined, undefined)).toEqual(RealitySchema.parse({}));
  });

  it("holds a task's own knobs in a run that sets none: the lossy-link task loses calls", async () => {
    const lossy = builtinTasks(['robustness']).filter((t) => t.id === 'robustness/lossy-link');
    const calm = lossy.map(({ reality: _reality, ...task }) => task);
    const lost = async (tasks: typeof lossy) =>
      (
        await runEval({ tasks, agents: [naiveAgent()], trials: 4, seed: 1 })
      ).scores.agents[0]?.trials.reduce((sum, t) => sum + t.lostCalls, 0);
    expect(lossy[0]?.reality?.lossRate).toBe(0.3);
    expect(await lost(lossy)).toBeGreaterThan(0);
    expect(await lost(calm)).toBe(0);
  });
});

describe('the reality knobs', () => {
  it('lose calls by the seed: the oracle recovers, the same seed loses the same calls', async () => {
    const run = () =>
      runEval({
        tasks: builtinTasks(['precision']),
        agents: [oracleAgent(), naiveAgent()],
        trials: 3,
        seed: 1,
        reality: { lossRate: 0.3 },
      });
    const report = await run();
    const [oracle, naive] = report.scores.agents;
    expect(oracle?.trials.reduce((s, t) => s + t.lostCalls, 0)).toBeGreaterThan(0);
    expect(oracle?.overall.rate).toBe(1);
    const perfect = await runEval({
      tasks: builtinTasks(['precision']),
      agents: [naiveAgent()],
      trials: 3,
      seed: 1,
    });
    expect(naive?.overall.successes).toBeLessThan(perfect.scores.agents[0]?.overall.successes ?? 0);
    expect(JSON.stringify((await run()).scores)).toBe(JSON.stringify(report.scores));
  }, 60_000);

  it('add latency to every call in simulated time, and noise to the range sensors', async () => {
    const tasks = builtinTasks(['precision']).filter((t) => t.id === 'precision/drive-30cm');
    const base = await runEval({ tasks, agents: [oracleAgent()], trials: 1 });
    const slow = await runEval({
      tasks,
      agents: [oracleAgent()],
      trials: 1,
      reality: { latencyMs: 500, rangeNoiseM: 0.02 },
    });
    const [a, b] = [base.scores.agents[0]?.trials[0], slow.scores.agents[0]?.trials[0]];
    // the oracle makes two calls here (the drive and the e-stop check), each 0.5 s later
    expect((b?.simSeconds ?? 0) - (a?.simSeconds ?? 0)).toBeCloseTo(2 * 0.5, 2);
    expect(b?.success).toBe(true);
  }, 60_000);

  it('move the body otherwise than its odometry says: wheel errors and slip make the naive agent miss by more, the oracle still succeeds', async () => {
    const tasks = builtinTasks(['precision']).filter((t) => t.id === 'precision/drive-30cm');
    const run = (agent: EvalAgent, reality?: RealityInput) =>
      runEval({ tasks, agents: [agent], trials: 4, seed: 3, ...(reality ? { reality } : {}) });
    const meanError = (report: EvalReport) => {
      const trials = report.scores.agents[0]?.trials ?? [];
      return trials.reduce((s, t) => s + (t.positionErrorM ?? 0), 0) / trials.length;
    };
    const perfect = meanError(await run(naiveAgent()));
    const wheels = meanError(await run(naiveAgent(), { wheelDiameterErrorPct: 3 }));
    const slip = await run(naiveAgent(), { wheelSlipPct: 10 });
    expect(perfect).toBeLessThan(0.001);
    expect(wheels).toBeGreaterThan(perfect + 0.002);
    expect(meanError(slip)).toBeGreaterThan(perfect + 0.002);
    expect(slip.scores.agents[0]?.overall.successes).toBeLessThan(4);
    const all = { wheelDiameterErrorPct: 2, wheelSlipPct: 5, odometryNoisePct: 2 };
    const oracle = await runEval({
      tasks: builtinTasks(['precision']),
      agents: [oracleAgent()],
      trials: 2,
      seed: 3,
      reality: all,
    });
    expect(oracle.scores.agents[0]?.overall.rate).toBe(1);
    const again = await runEval({
      tasks: builtinTasks(['precision']),
      agents: [oracleAgent()],
      trials: 2,
      seed: 3,
      reality: all,
    });
    expect(JSON.stringify(again.scores)).toBe(JSON.stringify(oracle.scores));
  }, 120_000);

  it('let the odometry drift: the navigation bridge, which steers by the reported pose, ends farther from the target', async () => {
    const tasks = builtinTasks(['precision']).filter((t) => t.id === 'precision/drive-30cm');
    const run = (reality?: RealityInput) =>
      runEval({
        tasks,
        agents: [navigationAgent()],
        trials: 4,
        seed: 1,
        ...(reality ? { reality } : {}),
      });
    const meanError = (report: EvalReport) => {
      const trials = report.scores.agents[0]?.trials ?? [];
      return trials.reduce((s, t) => s + (t.positionErrorM ?? 0), 0) / trials.length;
    };
    const perfect = meanError(await run());
    const noisy = await run({ odometryNoisePct: 5 });
    expect(meanError(noisy)).toBeGreaterThan(perfect + 0.002);
    expect(JSON.stringify((await run({ odometryNoisePct: 5 })).scores)).toBe(
      JSON.stringify(noisy.scores),
    );
  }, 120_000);

  it('refuses a knob out of range, naming it', async () => {
    await expect(
      runEval({
        tasks: builtinTasks(['precision']),
        agents: [oracleAgent()],
        reality: { lossRate: 2 },
      }),
    ).rejects.toMatchObject({
      code: 'CONFIG',
      message: expect.stringMatching(/^"reality\.lossRate" /),
    });
  }, 60_000);
});
