// `hal record` around the emulated cube over real UDP (several motions and an e-stop), then
// `hal inspect` and `hal replay` on the simulator: the replay agrees with the robot within the
// twin agreement the project holds (about 0.2 mm, whole steps equal).
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { readRecordingFile } from '@hal/recorder';
import { afterAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { LONGEST_HOST_TIMEOUT_MS, startEmulator, stopAllEmulators } from '../physical/emulator.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-record-emulator-'));
afterAll(async () => {
  await stopAllEmulators();
  rmSync(dir, { recursive: true, force: true });
});

async function halJson(argv: string[]): Promise<{ code: number; value: Record<string, unknown> }> {
  const io = captureIO();
  const code = await runHal(['--json', ...argv], io);
  expect(code, io.stderr()).toBe(0);
  return {
    code,
    value: JSON.parse(io.stdout().trim().split('\n').at(-1)!) as Record<string, unknown>,
  };
}

describe('a run of the emulated cube, recorded and replayed', () => {
  it('records the motions and the e-stop, and replays them on the simulator within 0.2 mm, steps equal', async () => {
    // the longest host timeout: at 8x the default 2 s is 250 ms of real time, which a loaded
    // machine can hold a heartbeat back for, and the robot would stop a motion for it
    const emulator = await startEmulator({
      pty: false,
      timeScale: 8,
      deviceId: 'cube-rec',
      hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS,
    });
    const file = join(dir, 'cube.mcap');
    try {
      const { value: recorded } = await halJson([
        'record',
        '-o',
        file,
        '--udp',
        `127.0.0.1:${emulator.udpPort}`,
        '--time-scale',
        '8',
        'forward 0.1',
        'turn 90',
        'forward -0.05',
        'turn -45',
        'estop operator test',
        'forward 0.05',
        'reset-estop',
        'move-to 0.05 0.1',
      ]);
      expect(recorded['steps']).toEqual([
        { step: 'forward 0.1', success: true },
        { step: 'turn 90', success: true },
        { step: 'forward -0.05', success: true },
        { step: 'turn -45', success: true },
        { step: 'estop operator test', success: true },
        { step: 'forward 0.05', success: false, code: 'EMERGENCY_STOPPED' },
        { step: 'reset-estop', success: true },
        { step: 'move-to 0.05 0.1', success: true },
      ]);
      expect(recorded['recorder']).toMatchObject({ dropped: 0 });
      expect(
        (await emulator.waitForCount((e) => e.event === 'move_finished', 5)).length,
      ).toBeGreaterThanOrEqual(5);
    } finally {
      await emulator.stop();
    }

    const recording = await readRecordingFile(file);
    expect(recording.complete).toBe(true);
    expect(recording.metadata.get('hal.robot')).toMatchObject({
      mode: 'physical',
      device_id: 'cube-rec',
    });

    // the robot's own reports: its step counters and the link's figures, on their channels
    expect(recording.channels.get('/hal/steps')?.schemaName).toBe('hal.WheelSteps');
    expect(recording.channels.get('/hal/steps')?.messageCount).toBeGreaterThan(4);
    const link = recording.messages.filter((m) => m.topic === '/hal/link').at(-1)?.value;
    expect(link).toMatchObject({ link_state: 'connected', timeouts: 0 });

    const { value: inspected } = await halJson(['inspect', file]);
    expect(inspected).toMatchObject({
      complete: true,
      errors: 1,
      errorsByCode: { EMERGENCY_STOPPED: 1 },
      emergencyStops: 1,
      dropped: 0,
    });
    expect(inspected['calls']).toBeGreaterThanOrEqual(8);

    const svg = join(dir, 'cube.svg');
    const { value: replay } = await halJson(['replay', file, '--svg', svg]);
    const calls = replay['calls'] as Array<{
      call: string;
      positionM?: number;
      steps?: { recorded: number[]; replayed: number[] };
    }>;
    expect(calls.map((c) => c.call)).toEqual([
      'locomotion.moveForward',
      'locomotion.rotate',
      'locomotion.moveBackward',
      'locomotion.rotate',
      'safety.emergencyStop',
      'locomotion.moveForward',
      'safety.resetEmergencyStop',
      'locomotion.moveTo',
    ]);
    expect(replay['outcomeMismatches']).toBe(0);
    expect(replay['maxPositionM'] as number).toBeLessThan(0.0002);
    expect(replay['stepMismatches']).toBe(0);
    // the four motions, and the e-stop (the steps of the motion it ended), reported their wheel
    // steps on both sides, so "equal" compared something
    expect(calls.filter((c) => c.steps !== undefined).map((c) => c.call)).toEqual([
      'locomotion.moveForward',
      'locomotion.rotate',
      'locomotion.moveBackward',
      'locomotion.rotate',
      'safety.emergencyStop',
    ]);
    expect(readFileSync(svg, 'utf8')).toContain('<polyline');
  }, 60_000);
});
