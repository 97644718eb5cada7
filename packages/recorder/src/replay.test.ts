import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { memorySink } from './file-sink.js';
import { readRecording } from './read-recording.js';
import type { Recording } from './read-recording.js';
import { recordHal } from './record-hal.js';
import { McapRecorder } from './recorder.js';
import { replayRecording } from './replay.js';
import { summarizeRecording } from './summary.js';
import { trajectorySvg } from './trajectory-svg.js';

async function recordedRun(): Promise<Recording> {
  const sink = memorySink();
  const recorder = await McapRecorder.create(sink);
  const hal = recordHal(new SimulationHAL(), recorder, { posePeriodMs: 0 });
  await hal.initialize();
  await hal.locomotion.moveForward(10);
  await hal.locomotion.rotate('left', 90);
  await hal.locomotion.moveTo(0.1, 0.1, 0);
  await hal.safety.emergencyStop('replay test');
  await hal.locomotion.moveForward(5);
  await hal.safety.resetEmergencyStop();
  await hal.locomotion.getPose();
  await hal.cleanup();
  await recorder.close();
  return readRecording(sink.bytes());
}

describe('replayRecording', () => {
  it('re-runs the action calls on a fresh simulator with no divergence and the same outcomes', async () => {
    const recording = await recordedRun();
    const sim = new SimulationHAL();
    await sim.initialize();
    const report = await replayRecording(recording, sim);
    await sim.cleanup();
    expect(report.calls.map((c) => c.call)).toEqual([
      'locomotion.moveForward',
      'locomotion.rotate',
      'locomotion.moveTo',
      'safety.emergencyStop',
      'locomotion.moveForward',
      'safety.resetEmergencyStop',
    ]);
    expect(report.calls[4]).toMatchObject({
      recorded: { success: false, code: 'EMERGENCY_STOPPED' },
      replayed: { success: false, code: 'EMERGENCY_STOPPED' },
    });
    expect(report.outcomeMismatches).toBe(0);
    expect(report.maxPositionM).toBeLessThan(1e-9);
    expect(report.calls.every((c) => c.positionM !== undefined)).toBe(true);
    const svg = trajectorySvg(report);
    expect(svg).toContain('<polyline');
    expect(svg).toContain('max divergence 0.000 mm');
  });

  it('shows the divergence of a robot that did not start where the recording did', async () => {
    const recording = await recordedRun();
    const sim = new SimulationHAL();
    await sim.initialize();
    await sim.locomotion.moveForward(3);
    const report = await replayRecording(recording, sim);
    await sim.cleanup();
    // 3 cm ahead after the first move, and still apart after the turn and the move-to
    expect(report.calls[0]!.positionM).toBeCloseTo(0.03, 3);
    expect(report.maxPositionM).toBeGreaterThan(0.029);
  });
});

describe('summarizeRecording', () => {
  it('counts the calls, errors, e-stops and messages per channel', async () => {
    const summary = summarizeRecording(await recordedRun());
    expect(summary).toMatchObject({
      complete: true,
      calls: 9,
      errors: 1,
      errorsByCode: { EMERGENCY_STOPPED: 1 },
      emergencyStops: 1,
      trips: 0,
      dropped: 0,
    });
    expect(summary.channels['/hal/calls']).toEqual({ schema: 'hal.CallRecord', messages: 9 });
    expect(summary.durationS).toBeGreaterThan(0);
  });
});
