import {
  COMPRESSED_IMAGE,
  McapRecorder,
  memorySink,
  POSE_IN_FRAME,
  recordHal,
} from '@hal/recorder';
import { SimulationHAL, World } from '@hal/simulation';
import type { Pose } from '@hal/types';
import type * as WasmZstd from '@foxglove/wasm-zstd';
import { describe, expect, it, vi } from 'vitest';
import { readTimeline } from './read-timeline.js';
import { RecordingFileError } from './recording-file-error.js';

// The recordings below are written with Foxglove's zstd and read with the browser's stand-in,
// as the demo reads a file recorded in Node.
const browserDecompress = vi.hoisted(() => ({ calls: 0 }));
vi.mock('@foxglove/wasm-zstd', async (importActual) => {
  const actual = await importActual<typeof WasmZstd>();
  const browser = await import('./zstd-browser.js');
  return {
    ...actual,
    decompress: (buffer: Uint8Array, size: number) => {
      browserDecompress.calls += 1;
      return browser.decompress(buffer, size);
    },
  };
});

/** A simulated run recorded on the world's clock: poses after each move, a frame after each. */
async function recordedRun(): Promise<{ bytes: Uint8Array; poses: Pose[]; frames: number }> {
  const world = new World({ map: 'empty', seed: 1 });
  const sink = memorySink();
  const epochNs = 1_700_000_000_000_000_000n;
  const recorder = await McapRecorder.create(sink, {
    clock: () => epochNs + BigInt(world.nowUs) * 1000n,
  });
  const hal = recordHal(new SimulationHAL({ world }), recorder, { posePeriodMs: 0 });
  await hal.initialize();
  const poses: Pose[] = [];
  let frames = 0;
  for (const move of [
    () => hal.locomotion.moveForward(20),
    () => hal.locomotion.rotate('left', 90),
    () => hal.locomotion.moveForward(10),
  ]) {
    expect((await move()).success).toBe(true);
    poses.push(await hal.locomotion.getPose());
    await hal.vision.captureFrame();
    frames += 1;
  }
  await hal.cleanup();
  await recorder.close();
  return { bytes: sink.bytes(), poses, frames };
}

// A run renders camera frames in software: seconds on a loaded machine, not the default 5 s.
const RUN_TIMEOUT_MS = 30_000;

describe('readTimeline', () => {
  it(
    'reads a zstd recording of a simulated run into its poses and camera frames',
    async () => {
      const run = await recordedRun();
      browserDecompress.calls = 0;
      const timeline = await readTimeline('run.mcap', run.bytes);
      expect(browserDecompress.calls).toBeGreaterThan(0);
      expect(timeline.truncation).toBeUndefined();
      expect(timeline.frames).toHaveLength(run.frames);
      expect(timeline.frames[0]?.src).toMatch(/^data:image\/jpeg;base64,\/9j\//);
      expect(timeline.deviceId).toBe('sim-robot-1');
      expect(timeline.calls).toBeGreaterThanOrEqual(7); // initialize, 3 moves, 3 frames, cleanup
      // each move's pose is on the time line, at a later time than the one before
      const last = timeline.poses[timeline.poses.length - 1];
      const final = run.poses[run.poses.length - 1];
      expect(last?.x).toBeCloseTo(final?.position.x ?? NaN, 9);
      expect(last?.y).toBeCloseTo(final?.position.y ?? NaN, 9);
      expect(last?.yaw).toBeCloseTo(final?.rotation.yaw ?? NaN, 9);
      for (const pose of run.poses) {
        expect(
          timeline.poses.some(
            (p) => Math.abs(p.x - pose.position.x) < 1e-9 && Math.abs(p.y - pose.position.y) < 1e-9,
          ),
        ).toBe(true);
      }
      const times = timeline.poses.map((p) => p.t);
      expect(times).toEqual([...times].sort((a, b) => a - b));
      // the world's clock: 30 cm and a quarter turn at the V1 cube's 4.7 cm/s take seconds
      expect(timeline.durationMs).toBeGreaterThan(5000);
    },
    RUN_TIMEOUT_MS,
  );

  it("plays Foxglove's pose (yaw from its quaternion) when the file has no HAL pose", async () => {
    const sink = memorySink();
    let now = 1_000_000_000n;
    const recorder = await McapRecorder.create(sink, { compression: 'none', clock: () => now });
    recorder.channel('/hal/pose', POSE_IN_FRAME);
    const yaw = 2.5;
    for (const x of [0, 0.5]) {
      const orientation = { x: 0, y: 0, z: Math.sin(yaw / 2), w: Math.cos(yaw / 2) };
      recorder.write('/hal/pose', {
        timestamp: { sec: 1, nsec: 0 },
        frame_id: 'world',
        pose: { position: { x, y: -0.25, z: 0 }, orientation },
      });
      now += 2_000_000_000n;
    }
    await recorder.close();
    const timeline = await readTimeline('foxglove.mcap', sink.bytes());
    expect(timeline.poses).toEqual([
      { t: 0, x: 0, y: -0.25, yaw: expect.closeTo(2.5, 9) as number },
      { t: 2000, x: 0.5, y: -0.25, yaw: expect.closeTo(2.5, 9) as number },
    ]);
    expect(timeline.frames).toEqual([]);
  });

  it('refuses a file that is not MCAP with NOT_MCAP, naming the file', async () => {
    const text = new TextEncoder().encode('x,y\n0,0\n');
    const error = await readTimeline('poses.csv', text).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(RecordingFileError);
    expect(error).toMatchObject({
      code: 'NOT_MCAP',
      message: expect.stringContaining('poses.csv'),
    });
  });

  it("refuses an empty file, MCAP's magic alone and a garbled recording, with the reason", async () => {
    const empty = await readTimeline('empty.mcap', new Uint8Array(0)).catch((e: unknown) => e);
    expect(empty).toBeInstanceOf(RecordingFileError);
    expect(empty).toMatchObject({ code: 'EMPTY', message: expect.stringContaining('empty.mcap') });
    const magic = new Uint8Array([0x89, 0x4d, 0x43, 0x41, 0x50, 0x30, 0x0d, 0x0a]);
    const bare = await readTimeline('magic.mcap', magic).catch((e: unknown) => e);
    expect(bare).toMatchObject({
      code: 'NO_HEADER',
      message: expect.stringContaining('magic.mcap'),
    });
    // a recording whose only chunk is overwritten: nothing in it can be read
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink, { compression: 'none' });
    recorder.channel('/hal/pose', POSE_IN_FRAME);
    recorder.write('/hal/pose', {
      timestamp: { sec: 1, nsec: 0 },
      frame_id: 'world',
      pose: { position: { x: 1, y: 0, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
    });
    await recorder.close();
    const bytes = sink.bytes();
    const chunkAt = bytes.indexOf(0x06, 8 + 29);
    bytes.fill(0x41, chunkAt + 9, chunkAt + 120);
    const garbled = await readTimeline('garbled.mcap', bytes).catch((e: unknown) => e);
    expect(garbled).toMatchObject({
      code: 'DAMAGED',
      message: expect.stringContaining(`garbled.mcap is damaged`),
    });
  });

  it("refuses an MCAP file with none of the robot's topics, naming the topics it has", async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink, { compression: 'none' });
    recorder.channel('/other/images', COMPRESSED_IMAGE);
    await recorder.close();
    const error = await readTimeline('other.mcap', sink.bytes()).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(RecordingFileError);
    expect(error).toMatchObject({ code: 'NO_ROBOT_TOPICS' });
    expect((error as Error).message).toContain('/other/images');
    expect((error as Error).message).toContain('/hal/pose');
  });

  it(
    'refuses a file cut short before any robot message, saying where reading stopped',
    async () => {
      const run = await recordedRun();
      const error = await readTimeline('cut.mcap', run.bytes.slice(0, 40)).catch((e: unknown) => e);
      expect(error).toMatchObject({ code: 'NO_ROBOT_TOPICS' });
      expect((error as Error).message).toMatch(/read up to/);
    },
    RUN_TIMEOUT_MS,
  );
});
