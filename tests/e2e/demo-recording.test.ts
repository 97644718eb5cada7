// The demo's flight recorder in a real browser (Debian's Chromium, driven by playwright-core):
// record a drive and download it as MCAP, then read the file back in Node with @mcap/core's
// reader (through @hal/recorder); load a file recorded in Node (recordHal over SimulationHAL)
// into the page and check that the scene's robot follows its poses and the camera panel shows
// its frames (a screenshot of it goes to artifacts/demo-playback.png); and see files that
// cannot be played refused on the card.
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  COMPRESSED_IMAGE,
  McapRecorder,
  readRecordingFile,
  recordHal,
  TOPICS,
} from '@hal/recorder';
import type { HalCallRecord, RecordedMessage } from '@hal/recorder';
import { SimulationHAL, World } from '@hal/simulation';
import type { Pose } from '@hal/types';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openDemoInChromium } from './demo-browser.js';
import type { DemoBrowser } from './demo-browser.js';

const artifacts = fileURLToPath(new URL('../../artifacts', import.meta.url));

interface RecordingState {
  recording: boolean;
  written: number;
  framesCaptured: number;
  message: string;
  playback: null | {
    name: string;
    durationMs: number;
    t: number;
    playing: boolean;
    poses: number;
    frames: number;
    calls: number;
    drawn: { x: number; y: number; yaw: number } | null;
    frameSrc: string | null;
  };
}

interface DemoWindow {
  simDemo: {
    pose(): { x: number; y: number; yaw: number };
    recording(): RecordingState;
  };
}

/** A run recorded in Node on the world's clock: three moves, a camera frame after each. */
async function recordInNode(path: string): Promise<void> {
  const world = new World({ map: 'empty', seed: 1 });
  const epochNs = 1_700_000_000_000_000_000n;
  const recorder = await McapRecorder.toFile(path, {
    clock: () => epochNs + BigInt(world.nowUs) * 1000n,
  });
  const hal = recordHal(new SimulationHAL({ world }), recorder, {
    posePeriodMs: 0,
    map: { name: 'empty' },
  });
  await hal.initialize();
  for (const move of [
    () => hal.locomotion.moveForward(30),
    () => hal.locomotion.rotate('left', 90),
    () => hal.locomotion.moveForward(20),
  ]) {
    expect((await move()).success).toBe(true);
    await hal.vision.captureFrame();
  }
  await hal.cleanup();
  await recorder.close();
}

/** Log time in ms from the first of `messages`. */
function msFrom(first: RecordedMessage, m: RecordedMessage): number {
  return Number(m.logTime - first.logTime) / 1e6;
}

describe("the demo's recording, in Chromium", () => {
  let demo: DemoBrowser;
  let page: Page;
  let dir: string;

  const state = () => page.evaluate(() => (window as unknown as DemoWindow).simDemo.recording());
  const livePose = () => page.evaluate(() => (window as unknown as DemoWindow).simDemo.pose());
  const seek = (t: number) =>
    page.evaluate((to) => {
      const slider = document.getElementById('playback-slider') as HTMLInputElement;
      slider.value = String(to);
      slider.dispatchEvent(new Event('input'));
    }, t);

  beforeAll(async () => {
    dir = mkdtempSync(join(tmpdir(), 'demo-recording-'));
    demo = await openDemoInChromium('demo-recording');
    page = demo.page;
    await page.goto(`${demo.url}?map=empty&speed=5`, { waitUntil: 'load', timeout: 20_000 });
    await page.waitForFunction(
      () => (window as unknown as { simDemo?: unknown }).simDemo !== undefined,
      undefined,
      { timeout: 15_000 },
    );
  }, 60_000);

  afterAll(async () => {
    await demo?.close();
    rmSync(dir, { recursive: true, force: true });
  }, 30_000);

  it('records a drive and downloads it as an MCAP file that holds its calls, poses and frames', async () => {
    const start = await livePose();
    await page.locator('#record-button').click();
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.recording().recording,
      undefined,
      { timeout: 10_000 },
    );
    await expect(page.locator('#recording-badge').textContent()).resolves.toBe('REC');
    expect((await state()).message).toMatch(/^Recording sim-robot-1 \(only this robot\)/);

    // drive forward with the keyboard, then let go
    await page.locator('#viewport > canvas').focus();
    await page.keyboard.down('ArrowUp');
    await page.waitForFunction(
      (x0) => (window as unknown as DemoWindow).simDemo.pose().x > x0 + 0.15,
      start.x,
      { timeout: 20_000 },
    );
    await page.keyboard.up('ArrowUp');
    await page.waitForFunction(
      () => document.getElementById('status')?.textContent === 'Stopped',
      undefined,
      { timeout: 10_000 },
    );
    // the robot has come to rest, and the camera has been captured into the file
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.recording().framesCaptured >= 2,
      undefined,
      { timeout: 10_000 },
    );
    const end = await livePose();

    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 15_000 }),
      page.locator('#record-button').click(),
    ]);
    expect(download.suggestedFilename()).toMatch(/^hal-demo-.+\.mcap$/);
    const path = join(dir, download.suggestedFilename());
    await download.saveAs(path);
    await expect(page.locator('#recording-message').textContent()).resolves.toMatch(
      /^Saved hal-demo-.+\.mcap: \d+ messages, \d+ KiB\.$/,
    );
    expect((await state()).recording).toBe(false);

    const recording = await readRecordingFile(path);
    expect(recording.complete).toBe(true);
    expect(recording.chunkCount).toBeGreaterThan(0);
    const calls = recording.messages
      .filter((m) => m.topic === TOPICS.calls)
      .map((m) => m.value as HalCallRecord);
    const drive = calls.find((c) => c.call === 'locomotion.drive');
    expect(drive?.success).toBe(true);
    const [left, right] = (drive?.args ?? []) as number[];
    expect(left).toBeGreaterThan(0);
    expect(right).toBe(left);
    const stop = calls.find((c) => c.call === 'locomotion.stop');
    expect(stop?.success).toBe(true);
    expect(calls.some((c) => c.call === 'vision.captureFrame' && c.success)).toBe(true);

    const poses = recording.messages
      .filter((m) => m.topic === TOPICS.halPose)
      .map((m) => m.value as Pose);
    expect(poses.length).toBeGreaterThan(3);
    // from where the drive started to where it came to rest, never going backwards
    expect(poses[0]?.position.x).toBeCloseTo(start.x, 3);
    expect(poses[poses.length - 1]?.position.x).toBeCloseTo(end.x, 3);
    const xs = poses.map((p) => p.position.x);
    expect(xs).toEqual([...xs].sort((a, b) => a - b));
    expect(recording.channels.get(TOPICS.tf)?.messageCount).toBe(poses.length);

    const frames = recording.messages.filter((m) => m.topic === TOPICS.camera);
    expect(frames.length).toBeGreaterThanOrEqual(2);
    expect((frames[0]?.value as { data: string }).data).toMatch(/^\/9j\//); // a JPEG
    const robot = recording.metadata.get('hal.robot');
    expect(robot?.['device_id']).toBe('sim-robot-1');
    expect(JSON.parse(robot?.['map'] ?? 'null')).toEqual({ name: 'empty' });
    expect(demo.problems).toEqual([]);
  }, 120_000);

  it("plays a file recorded in Node: the scene's robot follows its poses, the camera its frames", async () => {
    const path = join(dir, 'node-run.mcap');
    await recordInNode(path);
    const recording = await readRecordingFile(path);
    const timed = recording.messages.filter(
      (m) => m.topic === TOPICS.halPose || m.topic === TOPICS.camera,
    );
    const first = timed[0];
    if (first === undefined) throw new Error('the Node recording has no poses');
    const poses = timed.filter((m) => m.topic === TOPICS.halPose);
    const frames = timed.filter((m) => m.topic === TOPICS.camera);
    const live = await livePose();

    await page.locator('#mcap-input').setInputFiles(path);
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.recording().playback !== null,
      undefined,
      { timeout: 15_000 },
    );
    const loaded = (await state()).playback;
    expect(loaded).toMatchObject({
      name: 'node-run.mcap',
      poses: poses.length,
      frames: frames.length,
      playing: false,
    });
    expect(loaded?.durationMs).toBeCloseTo(msFrom(first, timed[timed.length - 1] ?? first), 3);
    await expect(page.locator('#recording-badge').textContent()).resolves.toBe('PLAYBACK');

    // at every recorded pose's time, the scene draws the robot exactly there
    for (const message of poses) {
      await seek(msFrom(first, message));
      const pose = message.value as Pose;
      const drawn = (await state()).playback?.drawn;
      expect(drawn?.x).toBeCloseTo(pose.position.x, 9);
      expect(drawn?.y).toBeCloseTo(pose.position.y, 9);
      expect(drawn?.yaw).toBeCloseTo(pose.rotation.yaw, 9);
    }
    // the camera panel shows the frame recorded at that time, decoded as a 320x240 image
    const lastFrame = frames[frames.length - 1];
    await seek(msFrom(first, lastFrame ?? first));
    const shown = (await state()).playback?.frameSrc ?? '';
    expect(shown).toBe(`data:image/jpeg;base64,${(lastFrame?.value as { data: string }).data}`);
    await page.waitForFunction(
      () => (document.getElementById('playback-frame') as HTMLImageElement).naturalWidth === 320,
      undefined,
      { timeout: 5_000 },
    );
    await expect(page.locator('#playback-frame').isVisible()).resolves.toBe(true);
    mkdirSync(artifacts, { recursive: true });
    await page.screenshot({ path: join(artifacts, 'demo-playback.png') });

    // played from 1.5 s before the end, it runs to the end and stops on the last pose
    const duration = loaded?.durationMs ?? 0;
    await seek(duration - 1500);
    await page.locator('#playback-toggle').click();
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.recording().playback?.playing === false,
      undefined,
      { timeout: 15_000 },
    );
    const ended = (await state()).playback;
    expect(ended?.t).toBe(duration);
    const lastPose = poses[poses.length - 1]?.value as Pose;
    expect(ended?.drawn?.x).toBeCloseTo(lastPose.position.x, 9);
    expect(ended?.drawn?.y).toBeCloseTo(lastPose.position.y, 9);

    // keys do not drive the live robot during playback
    await page.locator('#viewport > canvas').focus();
    await page.keyboard.down('ArrowUp');
    await page.waitForTimeout(300);
    await page.keyboard.up('ArrowUp');
    expect(await livePose()).toEqual(live);

    await page.locator('#playback-exit').click();
    expect((await state()).playback).toBeNull();
    await expect(page.locator('#recording-badge').textContent()).resolves.toBe('OFF');
    expect(demo.problems).toEqual([]);
  }, 120_000);

  it('refuses a file that is not MCAP, and one with none of the robot topics, changing nothing', async () => {
    await page.locator('#mcap-input').setInputFiles({
      name: 'notes.txt',
      mimeType: 'text/plain',
      buffer: Buffer.from('not a recording\n'),
    });
    await page.waitForFunction(
      () => document.getElementById('recording-message')?.getAttribute('role') === 'alert',
      undefined,
      { timeout: 10_000 },
    );
    let after = await state();
    expect(after.message).toBe(
      'notes.txt is not an MCAP file: it does not start with MCAP\'s magic bytes (it starts with 6e 6f 74 20 61 20 72 65 "not a re")',
    );
    expect(after.playback).toBeNull();

    const other = join(dir, 'other.mcap');
    const recorder = await McapRecorder.toFile(other);
    recorder.channel('/elsewhere/camera', COMPRESSED_IMAGE);
    recorder.write('/elsewhere/camera', {
      timestamp: { sec: 0, nsec: 0 },
      frame_id: 'c',
      data: '',
      format: 'jpeg',
    });
    await recorder.close();
    await page.locator('#mcap-input').setInputFiles(other);
    await page.waitForFunction(
      () => document.getElementById('recording-message')?.textContent?.startsWith('other.mcap'),
      undefined,
      { timeout: 10_000 },
    );
    after = await state();
    expect(after.message).toContain("other.mcap has none of the robot's topics");
    expect(after.message).toContain('/elsewhere/camera');
    expect(after.playback).toBeNull();
    await expect(page.locator('#recording-badge').textContent()).resolves.toBe('OFF');
    expect(demo.problems).toEqual([]);
  }, 60_000);
});
