// `hal eval --on`: the precision tasks on the emulated cube (the firmware core as a process)
// through PhysicalHAL over UDP, scored from what the robot reports, beside the simulator's rows.
import { runHal } from '@hal/cli';
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
    const args = ['--agent', 'naive', '--tasks', 'precision', '--trials', '1'];
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
    // the same calls on the same tasks: the robot's wheels step as the simulator's do
    expect(robot?.trials.map((t) => [t.task, t.success, t.toolCalls])).toEqual(
      sim?.trials.map((t) => [t.task, t.success, t.toolCalls]),
    );
  }, 120_000);

  it('refuses an unknown place as a usage error, naming it', async () => {
    const io = captureIO();
    expect(await runHal(['eval', '--on', 'sim,mars'], io)).toBe(2);
    expect(io.stderr()).toMatch(/"--on": unknown place "mars"/);
  });
});
