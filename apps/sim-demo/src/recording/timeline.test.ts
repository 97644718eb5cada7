import { describe, expect, it } from 'vitest';
import { frameAt, poseAt } from './timeline.js';

describe('poseAt and frameAt', () => {
  const poses = [
    { t: 0, x: 0, y: 0, yaw: 3 },
    { t: 100, x: 1, y: 2, yaw: -3 },
  ];

  it('interpolates between poses, turning the short way round', () => {
    const mid = poseAt(poses, 50);
    expect(mid?.x).toBeCloseTo(0.5, 9);
    expect(mid?.y).toBeCloseTo(1, 9);
    // from 3 rad to -3 rad the short way is through pi, not through 0
    expect(Math.cos(mid?.yaw ?? 0)).toBeCloseTo(-1, 3);
  });

  it('holds the first pose before it and the last after it, and has none without poses', () => {
    expect(poseAt(poses, -10)).toEqual({ x: 0, y: 0, yaw: 3 });
    expect(poseAt(poses, 500)).toEqual({ x: 1, y: 2, yaw: -3 });
    expect(poseAt([], 5)).toBeUndefined();
  });

  it('shows the last frame at or before a time', () => {
    const frames = [
      { t: 10, src: 'a' },
      { t: 20, src: 'b' },
    ];
    expect(frameAt(frames, 5)).toBeUndefined();
    expect(frameAt(frames, 10)?.src).toBe('a');
    expect(frameAt(frames, 19.9)?.src).toBe('a');
    expect(frameAt(frames, 99)?.src).toBe('b');
  });
});
