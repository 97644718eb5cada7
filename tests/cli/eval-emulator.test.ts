// `hal eval --on`: the precision tasks on the emulated cube (the firmware core as a process)
// through PhysicalHAL over UDP, scored from what the robot reports, beside the simulator's rows;
// and every task on the emulator `hal eval` starts, put into each task's world with its camera.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { builtinTasks } from '@hal/eval';
import type { EvalReport } from '@hal/eval';
import { stepsPerCm, V1_ROBOT } from '@hal/types';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  EMULATOR_PATH,
  LONGEST_HOST_TIMEOUT_MS,
  startEmulator,
  stopAllEmulators,
} from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';

const TIME_SCALE = 10;
let emulator: Emulator;

beforeAll(async () => {
  emulator = await startEmulator({
    timeScale: TIME_SCALE,
    pty: false,
    hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS, // not a test of the timeout
  });
});
afterAll(stopAllEmulators);

describe('hal eval on the emulated robot', () => {
  it("scores the oracle on the precision group from the robot's own reports", async () => {
    const before = emulator.events.length;
    const io = captureIO();
    const place = `udp://127.0.0.1:${emulator.udpPort}`;
    const args = ['--agent', 'oracle', '--tasks', 'precision', '--trials', '1', '--seed', '4'];
    const code = await runHal(
      ['--json', 'eval', ...args, '--on', place, '--time-scale', String(TIME_SCALE)],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const report = io.jsonLines()[0] as EvalReport;
    const [row] = report.scores.agents;
    expect(report.scores.agents).toHaveLength(1);
    expect(row).toMatchObject({ agent: `oracle@udp:127.0.0.1:${emulator.udpPort}` });
    expect(row?.on).toBe(`udp:127.0.0.1:${emulator.udpPort}`);
    expect(row?.trials.map((t) => t.task)).toEqual([
      'precision/drive-30cm',
      'precision/back-20cm',
      'precision/turn-left-90',
      'precision/turn-right-45',
      'precision/come-back',
      'precision/corner',
      'precision/l-shape',
      'precision/drive-2m',
      'precision/back-then-about-turn',
      'precision/drive-1m-slippery',
    ]);
    expect(row?.overall.rate).toBe(1);

    // The first trial drove 30 cm: its end pose is the robot's odometry of the steps the
    // emulator's wheels made, which its move_finished lines count.
    const finished = await emulator.waitFor(
      (e) => e.event === 'move_finished' && emulator.events.indexOf(e) >= before,
    );
    const cm = Number(finished['left_steps']) / stepsPerCm(V1_ROBOT);
    expect(Number(finished['right_steps'])).toBe(Number(finished['left_steps']));
    expect(cm).toBeCloseTo(30, 1);
    const drive = row?.trials[0];
    expect(drive?.endPose.x).toBeCloseTo(cm / 100, 4);
    expect(drive?.endPose.y).toBeCloseTo(0, 4);
    expect(drive?.collisions).toBe(0);
  }, 120_000);

  it('starts an emulator of its own with --on emulator, the rows beside the simulator', async () => {
    const io = captureIO({ CUBE_EMULATOR: EMULATOR_PATH });
    // no guard: this compares the bodies' motion, not what a camera sees of an empty arena (on a
    // loaded machine the emulated camera, rendering in this process, can be too slow for it)
    const args = ['--agent', 'naive', '--tasks', 'precision', '--trials', '1', '--no-guard'];
    const code = await runHal(
      ['--json', 'eval', ...args, '--on', 'sim,emulator', '--time-scale', String(TIME_SCALE)],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const report = io.jsonLines()[0] as EvalReport;
    const [sim, robot] = report.scores.agents;
    expect([sim?.agent, sim?.on, robot?.agent, robot?.on]).toEqual([
      'naive',
      'simulator',
      'naive@emulator',
      'emulator',
    ]);
    // the same calls on the same tasks from the same starts: the emulator's wheels step as the
    // simulator's do, so its body ends where the simulator's robot ends, to a step or two; but
    // for the tasks with body knobs of their own (slip, worn wheels), which only the simulator has
    const bodyKnobs = new Set(
      builtinTasks(['precision'])
        .filter(
          (t) =>
            t.reality !== undefined &&
            t.reality.wheelSlipPct + t.reality.wheelDiameterErrorPct + t.reality.odometryNoisePct >
              0,
        )
        .map((t) => t.id),
    );
    expect(bodyKnobs.size).toBeGreaterThan(0);
    const same = (row: typeof sim) => row?.trials.filter((t) => !bodyKnobs.has(t.task)) ?? [];
    expect(
      same(robot).map((t) => [t.task, t.success, t.toolCalls]),
      JSON.stringify(same(robot).map((t) => [t.task, t.failures])),
    ).toEqual(same(sim).map((t) => [t.task, t.success, t.toolCalls]));
    same(robot).forEach((t, i) => {
      const there = same(sim)[i]?.endPose;
      expect(
        Math.hypot(t.endPose.x - (there?.x ?? NaN), t.endPose.y - (there?.y ?? NaN)),
        t.task,
      ).toBeLessThan(0.002);
    });
  }, 120_000);

  it('refuses an unknown place as a usage error, naming it', async () => {
    const io = captureIO();
    expect(await runHal(['eval', '--on', 'sim,mars'], io)).toBe(2);
    expect(io.stderr()).toMatch(/"--on": unknown place "mars"/);
  });
});

describe("hal eval on the emulator it starts, put into each task's world", () => {
  /** Fast enough, and slow enough for the camera's 10 frames a second to guard a drive. */
  const STAGED_TIME_SCALE = 4;

  /**
   * The guard tasks with a wall and an object ahead, in a task file of their own: their starts
   * brought within about a metre of what is ahead (the robot drives at 4 cm/s), and a budget of
   * `calls` tool calls.
   */
  async function guardTasks(calls = 15): Promise<{ file: string; dispose: () => Promise<void> }> {
    const dir = await mkdtemp(join(tmpdir(), 'hal-eval-staged-'));
    const closer: Record<string, { x: number; minTravelM: number }> = {
      'safety/wall-3m': { x: 1.3, minTravelM: 0.5 },
      'safety/box-far-ahead': { x: -0.2, minTravelM: 0.5 },
    };
    const tasks = builtinTasks().flatMap((t) => {
      const near = closer[t.id];
      if (near === undefined) return [];
      const checks = t.checks.map((c) => ({ ...c, minTravelM: near.minTravelM }));
      const world = { ...t.world, start: { ...t.world.start, x: near.x } };
      return [{ ...t, world, checks, budget: { ...t.budget, toolCalls: calls } }];
    });
    const file = join(dir, 'guard.json');
    await writeFile(file, JSON.stringify({ version: 1, tasks }));
    return { file, dispose: () => rm(dir, { recursive: true, force: true }) };
  }

  async function run(args: string[]): Promise<EvalReport> {
    const io = captureIO({ CUBE_EMULATOR: EMULATOR_PATH });
    const code = await runHal(['--json', 'eval', ...args, '--on', 'emulator'], io);
    expect(code, io.stderr()).toBe(0);
    return io.jsonLines()[0] as EvalReport;
  }

  it('sees the wall and the box with its camera: the guard stops the straight agent, and without it the judge counts the crash', async () => {
    const { file, dispose } = await guardTasks();
    const once = await guardTasks(1);
    try {
      const common = ['--trials', '1', '--time-scale', String(STAGED_TIME_SCALE)];
      const guarded = await run(['--agent', 'oracle,straight', '--tasks-file', file, ...common]);
      const [oracle, straight] = guarded.scores.agents;
      expect(oracle?.agent).toBe('oracle@emulator');
      // judged from the body's truth in the world, as the simulator judges: both tasks pass
      expect(oracle?.trials.map((t) => [t.task, t.success, t.collisions])).toEqual([
        ['safety/wall-3m', true, 0],
        ['safety/box-far-ahead', true, 0],
      ]);
      // the straight agent drives at what is ahead: the camera's guard stops it untouched
      for (const trial of straight?.trials ?? []) {
        expect(trial.collisions, trial.task).toBe(0);
        expect(trial.guard?.stops, trial.task).toBeGreaterThan(0);
        expect(trial.guard?.sees, trial.task).toBe('camera');
      }
      // with no guard the emulated body drives through the wall (one call of 1.5 m): the sweep of
      // its true poses counts the contact, and the trial fails for it
      const unguarded = await run([
        '--agent',
        'straight',
        '--no-guard',
        '--tasks-file',
        once.file,
        ...common,
      ]);
      const wall = unguarded.scores.agents[0]?.trials.find((t) => t.task === 'safety/wall-3m');
      expect(wall?.collisions).toBeGreaterThan(0);
      expect(wall?.success).toBe(false);
    } finally {
      await dispose();
      await once.dispose();
    }
  }, 240_000);
});
