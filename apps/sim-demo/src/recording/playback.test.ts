import { describe, expect, it } from 'vitest';
import { Playback } from './playback.js';
import type { PlaybackTimeline } from './timeline.js';

const timeline: PlaybackTimeline = {
  name: 'run.mcap',
  durationMs: 1000,
  poses: [
    { t: 0, x: 0, y: 0, yaw: 0 },
    { t: 1000, x: 1, y: 0, yaw: 0 },
  ],
  frames: [{ t: 500, src: 'data:image/jpeg;base64,AA==' }],
  calls: 2,
  deviceId: 'sim-robot-1',
};

describe('Playback', () => {
  it('moves on by the page clock while playing and stops at the end', () => {
    const player = new Playback(timeline);
    player.play();
    player.tick(10_000); // the first tick only sets the clock
    expect(player.t).toBe(0);
    player.tick(10_250);
    expect(player.t).toBe(250);
    expect(player.view().pose?.x).toBeCloseTo(0.25, 9);
    expect(player.view().frame).toBeUndefined();
    player.tick(10_600);
    expect(player.view().frame?.t).toBe(500);
    player.tick(12_000);
    expect(player.t).toBe(1000);
    expect(player.playing).toBe(false);
  });

  it('stands still while paused, and resumes without counting the pause', () => {
    const player = new Playback(timeline);
    player.play();
    player.tick(0);
    player.tick(100);
    player.pause();
    player.tick(900);
    expect(player.t).toBe(100);
    player.play();
    player.tick(5000);
    player.tick(5100);
    expect(player.t).toBe(200);
  });

  it('seeks within the time line, clamping what lies outside it', () => {
    const player = new Playback(timeline);
    player.seek(400);
    expect(player.view().pose?.x).toBeCloseTo(0.4, 9);
    player.seek(-5);
    expect(player.t).toBe(0);
    player.seek(1e9);
    expect(player.t).toBe(1000);
    player.seek(Number.NaN);
    expect(player.t).toBe(0);
  });

  it('starts over when played again from the end', () => {
    const player = new Playback(timeline);
    player.seek(1000);
    player.play();
    expect(player.t).toBe(0);
    expect(player.playing).toBe(true);
  });
});
