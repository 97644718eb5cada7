// `hal fleet run --record FILE`: one recording of a whole fleet, each robot on its own channels
// under /<device>, summed up per robot by `hal inspect`. Three simulated robots through the real
// program (two processes: the run, then the inspection), and a simulated robot beside the
// emulated cube over UDP, whose reported steps and link statistics are on its channels too.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { readRecordingFile } from '@hal/recorder';
import type { HalCallRecord, LinkStats, RecordingSummary, WheelSteps } from '@hal/recorder';
import { afterAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { runHalProcess } from '../helpers/hal-process.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { expectWellFormed } from './well-formed.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-fleet-record-'));
afterAll(async () => {
  await stopAllEmulators();
  rmSync(dir, { recursive: true, force: true });
});

const lastJson = (stdout: string): Record<string, unknown> =>
  JSON.parse(stdout.trim().split('\n').at(-1)!) as Record<string, unknown>;

describe('hal fleet run --record', () => {
  it('records three simulated robots into one file, a channel set per robot, and inspect counts each', async () => {
    const config = join(dir, 'sims.json');
    writeFileSync(
      config,
      JSON.stringify({
        mode: 'synchronized',
        devices: ['sim-1', 'sim-2', 'sim-3'].map((id, i) => ({
          type: 'simulated',
          id,
          clock: 'fast',
          start: { x: 0, y: i * 0.4, yaw: 0 },
        })),
      }),
    );
    const file = join(dir, 'sims.mcap');
    const run = await runHalProcess(
      ['--json', 'fleet', 'run', '--config', config, '--command', 'forward:5cm', '--record', file],
      60_000,
    );
    expect(run.code, run.stderr).toBe(0);
    const report = lastJson(run.stdout);
    expect(report['succeeded']).toEqual(['sim-1', 'sim-2', 'sim-3']);
    expect(report['recording']).toMatchObject({ file, dropped: 0 });

    const recording = await readRecordingFile(file);
    expect(recording.complete).toBe(true);
    expectWellFormed(recording);
    expect(recording.metadata.get('hal.fleet')).toMatchObject({
      mode: 'synchronized',
      command: 'forward:5cm',
      devices: '["sim-1","sim-2","sim-3"]',
    });
    for (const [i, id] of ['sim-1', 'sim-2', 'sim-3'].entries()) {
      expect(recording.metadata.get(`hal.robot/${id}`)).toMatchObject({ device_id: id });
      const calls = recording.messages
        .filter((m) => m.topic === `/${id}/hal/calls`)
        .map((m) => m.value as HalCallRecord);
      expect(calls.find((c) => c.call === 'locomotion.moveForward')).toMatchObject({
        args: [5],
        success: true,
      });
      expect(calls[0]?.call).toBe('initialize');
      expect(calls.at(-1)?.call).toBe('cleanup');
      const tf = recording.messages.filter((m) => m.topic === `/${id}/tf`).at(-1)?.value as {
        child_frame_id: string;
        translation: { x: number; y: number };
      };
      expect(tf.child_frame_id).toBe(`${id}/base_link`);
      expect(tf.translation.x).toBeCloseTo(0.05, 3);
      expect(tf.translation.y).toBeCloseTo(i * 0.4, 3);
    }

    const inspected = await runHalProcess(['--json', 'inspect', file]);
    expect(inspected.code, inspected.stderr).toBe(0);
    const summary = lastJson(inspected.stdout) as unknown as RecordingSummary;
    expect(Object.keys(summary.robots ?? {})).toEqual(['sim-1', 'sim-2', 'sim-3']);
    for (const robot of Object.values(summary.robots ?? {})) {
      expect(robot).toMatchObject({ errors: 0, emergencyStops: 0 });
      expect(robot.calls).toBeGreaterThanOrEqual(3);
    }
    expect(summary.calls).toBe(
      Object.values(summary.robots ?? {}).reduce((sum, r) => sum + r.calls, 0),
    );
    const text = await runHalProcess(['inspect', file]);
    expect(text.stdout).toContain('a recording of 3 robots (sim-1, sim-2, sim-3)');
    expect(text.stdout).toMatch(/robot sim-2: calls \d+, errors 0/);

    // one robot of the fleet replayed on the simulator, from where it started
    const replayIo = captureIO();
    expect(await runHal(['--json', 'replay', file, '--robot', 'sim-2'], replayIo)).toBe(0);
    const replay = lastJson(replayIo.stdout());
    expect(replay).toMatchObject({ robot: 'sim-2', outcomeMismatches: 0, stepMismatches: 0 });
    expect((replay['calls'] as { call: string }[]).map((c) => c.call)).toEqual([
      'locomotion.moveForward',
    ]);
    expect(replay['maxPositionM'] as number).toBeLessThan(0.0002);
    const unnamed = captureIO();
    expect(await runHal(['replay', file], unnamed)).toBe(2);
    expect(unnamed.stderr()).toContain(
      'records 3 robots: name one with --robot (sim-1, sim-2, sim-3)',
    );
  }, 90_000);

  it('records a simulated robot beside the emulated cube, with the cube’s reported steps and link', async () => {
    const emulator = await startEmulator({ pty: false, deviceId: 'cube-1' });
    const config = join(dir, 'mixed.json');
    writeFileSync(
      config,
      JSON.stringify({
        mode: 'synchronized',
        devices: [
          { type: 'simulated', id: 'sim-1', clock: 'fast' },
          {
            type: 'physical',
            id: 'cube-1',
            connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
          },
        ],
      }),
    );
    const file = join(dir, 'mixed.mcap');
    const io = captureIO();
    try {
      const code = await runHal(
        [
          '--json',
          'fleet',
          'run',
          '--config',
          config,
          '--command',
          'forward:2cm',
          '--record',
          file,
        ],
        io,
      );
      expect(code, io.stderr()).toBe(0);
    } finally {
      await emulator.stop();
    }
    expect(lastJson(io.stdout())['succeeded']).toEqual(['sim-1', 'cube-1']);
    const recording = await readRecordingFile(file);
    expectWellFormed(recording);
    expect(recording.metadata.get('hal.robot/cube-1')).toMatchObject({ mode: 'physical' });
    // the simulator has no link: its channels hold no steps or link topic
    expect(recording.channels.has('/sim-1/hal/steps')).toBe(false);
    const steps = recording.messages
      .filter((m) => m.topic === '/cube-1/hal/steps')
      .map((m) => m.value as WheelSteps);
    // the fresh robot's counters after the one move are the steps that move reported
    const move = recording.messages
      .filter((m) => m.topic === '/cube-1/hal/calls')
      .map((m) => m.value as HalCallRecord)
      .find((c) => c.call === 'locomotion.moveForward');
    const moved = (move?.result as { data: { leftSteps: number; rightSteps: number } }).data;
    expect(moved.leftSteps).toBeGreaterThan(400); // 2 cm at 217.3 steps/cm
    expect(steps.at(-1)).toMatchObject({
      left_steps: moved.leftSteps,
      right_steps: moved.rightSteps,
    });
    const link = recording.messages
      .filter((m) => m.topic === '/cube-1/hal/link')
      .map((m) => m.value as LinkStats);
    expect(link.at(-1)).toMatchObject({ link_state: 'connected', timeouts: 0 });
    expect(link.at(-1)!.received).toBeGreaterThan(2);

    const summaryIo = captureIO();
    expect(await runHal(['--json', 'inspect', file], summaryIo)).toBe(0);
    const summary = lastJson(summaryIo.stdout()) as unknown as RecordingSummary;
    expect(summary.robots?.['cube-1']).toMatchObject({ errors: 0 });
    expect(summary.robots?.['cube-1']?.calls).toBeGreaterThanOrEqual(3);
  }, 60_000);
});
