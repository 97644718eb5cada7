import { readRecording, TOPICS } from '@hal/recorder';
import type { HalCallRecord } from '@hal/recorder';
import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { SessionRecorder } from './session-recorder.js';

describe('SessionRecorder', () => {
  it('records the calls made through it, the pose and camera frames, into a file it hands back', async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    const sessions = new SessionRecorder({ cameraPeriodMs: 20 });
    expect(sessions.halFor(hal)).toBe(hal);
    await sessions.start(hal, 'obstacles');
    const recorded = sessions.halFor(hal);
    expect(recorded).not.toBe(hal);
    expect((await recorded.locomotion.moveForward(10)).success).toBe(true);
    // wait (at most 10 s) until the recorder has captured two frames through the HAL
    let captured = 0;
    const capture = hal.vision.captureFrame.bind(hal.vision);
    hal.vision.captureFrame = async () => {
      const frame = await capture();
      captured += 1;
      return frame;
    };
    const deadline = Date.now() + 10_000;
    while (captured < 2 && Date.now() < deadline) await new Promise((r) => setTimeout(r, 10));
    expect(captured).toBeGreaterThanOrEqual(2);
    expect(sessions.capturedFrames()).toBeGreaterThanOrEqual(2);
    const { bytes, stats, fileName } = await sessions.stop();
    expect(sessions.recording).toBe(false);
    expect(sessions.halFor(hal)).toBe(hal);
    expect(fileName).toMatch(/^hal-demo-\d{4}-\d\d-\d\dT[\d-]+Z\.mcap$/);
    expect(stats.dropped).toBe(0);

    const recording = await readRecording(bytes);
    expect(recording.complete).toBe(true);
    const calls = recording.messages
      .filter((m) => m.topic === TOPICS.calls)
      .map((m) => m.value as HalCallRecord);
    const move = calls.find((c) => c.call === 'locomotion.moveForward');
    expect(move).toMatchObject({ args: [10], success: true });
    expect(move?.pose_after?.position.x).toBeCloseTo(
      (await hal.locomotion.getPose()).position.x,
      9,
    );
    expect(recording.channels.get(TOPICS.camera)?.messageCount ?? 0).toBeGreaterThanOrEqual(2);
    expect(calls.filter((c) => c.call === 'vision.captureFrame').length).toBeGreaterThanOrEqual(2);
    expect(JSON.parse(recording.metadata.get('hal.robot')?.['map'] ?? 'null')).toEqual({
      name: 'obstacles',
    });
    await hal.cleanup();
  }, 30_000); // frames rendered in software: seconds on a loaded machine

  it('waits at stop for the camera frame being captured, so it is in the file, not dropped', async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    const capture = hal.vision.captureFrame.bind(hal.vision);
    let release: () => void = () => undefined;
    const gate = new Promise<void>((resolve) => (release = resolve));
    let asked = 0;
    hal.vision.captureFrame = async () => {
      asked += 1;
      await gate;
      return capture();
    };
    const sessions = new SessionRecorder({ cameraPeriodMs: 10, captureWaitMs: 20_000 });
    await sessions.start(hal, 'empty');
    const deadline = Date.now() + 5_000;
    while (asked === 0 && Date.now() < deadline) await new Promise((r) => setTimeout(r, 5));
    expect(asked).toBe(1);
    let stopped = false;
    const stopping = sessions.stop().then((finished) => {
      stopped = true;
      return finished;
    });
    await new Promise((r) => setTimeout(r, 50));
    expect(stopped).toBe(false); // still waiting for the frame
    release();
    const { bytes, stats } = await stopping;
    expect(asked).toBe(1); // no capture started after stop
    expect(stats.dropped).toBe(0);
    const recording = await readRecording(bytes);
    expect(recording.channels.get(TOPICS.camera)?.messageCount).toBe(1);
    await hal.cleanup();
  }, 30_000);

  it('stops within captureWaitMs when a camera frame never comes', async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    let asked = 0;
    hal.vision.captureFrame = () => {
      asked += 1;
      return new Promise<string>(() => undefined);
    };
    const sessions = new SessionRecorder({ cameraPeriodMs: 10, captureWaitMs: 100 });
    await sessions.start(hal, 'empty');
    const deadline = Date.now() + 5_000;
    while (asked === 0 && Date.now() < deadline) await new Promise((r) => setTimeout(r, 5));
    expect(asked).toBe(1);
    const { bytes } = await sessions.stop();
    const recording = await readRecording(bytes);
    expect(recording.complete).toBe(true);
    expect(recording.channels.get(TOPICS.camera)?.messageCount ?? 0).toBe(0);
    await hal.cleanup();
  });

  it('refuses a second recording while one runs, and a stop with none running', async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    const sessions = new SessionRecorder();
    await expect(sessions.stop()).rejects.toThrow(/no recording/);
    await sessions.start(hal, 'empty');
    await expect(sessions.start(hal, 'empty')).rejects.toThrow(/already running/);
    await sessions.stop();
    await hal.cleanup();
  });
});
