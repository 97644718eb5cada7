import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { naiveAgent } from './agents/baselines.js';
import { oracleAgent } from './agents/oracle.js';
import { markdownReport } from './report/markdown.js';
import { builtinTasks } from './builtin-tasks.js';
import type { EvalRobot } from './robot-trial.js';
import { runsOnRobot } from './robot-trial.js';
import { runEval } from './run-eval.js';

// A simulator standing in for a robot: seen only through what it reports, as a PhysicalHAL is.
// (tests/cli/eval-emulator.test.ts runs the same on the emulated cube through PhysicalHAL.)
const twin = (): EvalRobot => ({
  name: 'twin',
  open: () => Promise.resolve(new SimulationHAL({ start: { x: 0.4, y: -0.2, yaw: 1 } })),
});

describe('runEval on a robot', () => {
  it('runs the tasks judged from the robot reports beside the simulator, in rows of their own', async () => {
    const report = await runEval({
      tasks: builtinTasks(),
      agents: [oracleAgent(), naiveAgent()],
      robots: [twin()],
      trials: 1,
    });
    const rows = report.scores.agents.map((a) => [a.agent, a.on]);
    expect(rows).toEqual([
      ['oracle', 'simulator'],
      ['naive', 'simulator'],
      ['oracle@twin', 'twin'],
      ['naive@twin', 'twin'],
    ]);
    const onRobot = builtinTasks().filter((t) => runsOnRobot(t));
    expect(onRobot.map((t) => t.group)).toContain('precision');
    const oracle = report.scores.agents[2];
    expect(oracle?.trials.map((t) => t.task)).toEqual(onRobot.map((t) => t.id));
    expect(oracle?.overall.rate).toBe(1);
    // the robot starts where it stands: its odometry's origin, whatever the simulator's start
    const drive = oracle?.trials.find((t) => t.task === 'precision/drive-30cm');
    expect(drive?.endPose.x).toBeCloseTo(0.3, 2);
    expect(drive?.endPose.y).toBeCloseTo(0, 3);
    const md = markdownReport(report);
    expect(md).toContain('from what the robot itself reports');
    expect(md).toContain('## oracle@twin\n\nOn twin, scored from what the robot reports.');
    // the same calls pass the same tasks, but for those whose own body knobs (slip, worn wheels)
    // hold only in the simulator: a robot has its own wheels
    const sameBody = (task: string) =>
      onRobot.some(
        (o) =>
          o.id === task &&
          (o.reality?.wheelSlipPct ?? 0) +
            (o.reality?.wheelDiameterErrorPct ?? 0) +
            (o.reality?.odometryNoisePct ?? 0) ===
            0,
      );
    const passed = (row: number) =>
      report.scores.agents[row]?.trials.filter((t) => sameBody(t.task) && t.success).length;
    expect(passed(3)).toBe(passed(1));
  }, 60_000);

  it('keeps out the tasks whose checks need ground truth, and says so when none is left', async () => {
    const goals = builtinTasks(['goals', 'perception']);
    expect(goals.some((t) => runsOnRobot(t))).toBe(false);
    await expect(
      runEval({ tasks: goals, agents: [oracleAgent()], robots: [twin()], trials: 1 }),
    ).rejects.toMatchObject({
      code: 'CONFIG',
      message: expect.stringMatching(/none of the tasks/),
    });
  });

  it('leaves a latch it did not set alone: the run fails with ROBOT and the robot stays stopped', async () => {
    const stopped = new SimulationHAL();
    const latched: EvalRobot = {
      name: 'cube-3',
      open: async () => {
        await stopped.safety.emergencyStop('pressed by a person');
        return stopped;
      },
    };
    await expect(
      runEval({
        tasks: builtinTasks(['precision']),
        agents: [oracleAgent()],
        robots: [latched],
        trials: 1,
      }),
    ).rejects.toMatchObject({
      code: 'ROBOT',
      message: expect.stringMatching(/^cube-3: the emergency stop is engaged/),
    });
    expect(stopped.safety.isEmergencyStopped()).toBe(true);
  });

  it('fails with ROBOT, naming the robot, when it cannot be reached', async () => {
    const offline: EvalRobot = {
      name: 'cube-7',
      open: () => Promise.reject(new Error('NOT_CONNECTED: no answer from 127.0.0.1:9')),
    };
    await expect(
      runEval({
        tasks: builtinTasks(['precision']),
        agents: [oracleAgent()],
        robots: [offline],
        trials: 1,
      }),
    ).rejects.toMatchObject({
      code: 'ROBOT',
      message: 'cube-7: NOT_CONNECTED: no answer from 127.0.0.1:9',
    });
  });
});
