import { describe, expect, it } from 'vitest';
import { composePose, divergenceBetween, relativeTo } from './divergence.js';

const tolerance = { positionToleranceM: 0.005, yawToleranceRad: 0.0175 };

describe('relativeTo', () => {
  it('expresses a pose in the frame of where the robot started', () => {
    const start = { x: 1, y: 2, yaw: Math.PI / 2 };
    const pose = relativeTo(start, { x: 1, y: 2.1, yaw: Math.PI });
    expect(pose.x).toBeCloseTo(0.1, 12);
    expect(pose.y).toBeCloseTo(0, 12);
    expect(pose.yaw).toBeCloseTo(Math.PI / 2, 12);
  });
});

describe('divergenceBetween', () => {
  it('measures the distance and the absolute heading difference across the +-pi seam', () => {
    const d = divergenceBetween(
      { x: 0, y: 0, yaw: Math.PI - 0.001 },
      { x: 0.003, y: 0.004, yaw: -Math.PI + 0.001 },
      tolerance,
    );
    expect(d.positionM).toBeCloseTo(0.005, 12);
    expect(d.yawRad).toBeCloseTo(0.002, 12);
    expect(d.exceeded).toBe(false);
  });

  it('is exceeded when either the position or the heading is beyond its tolerance', () => {
    expect(
      divergenceBetween({ x: 0, y: 0, yaw: 0 }, { x: 0.006, y: 0, yaw: 0 }, tolerance),
    ).toMatchObject({ exceeded: true });
    expect(
      divergenceBetween({ x: 0, y: 0, yaw: 0 }, { x: 0, y: 0, yaw: -0.02 }, tolerance),
    ).toMatchObject({ exceeded: true });
  });
});

describe('composePose', () => {
  it('undoes relativeTo', () => {
    const start = { x: 1, y: -1, yaw: 2 };
    const pose = { x: -0.3, y: 0.7, yaw: -2.5 };
    const back = composePose(start, relativeTo(start, pose));
    expect(back.x).toBeCloseTo(pose.x, 12);
    expect(back.y).toBeCloseTo(pose.y, 12);
    expect(back.yaw).toBeCloseTo(pose.yaw, 12);
  });
});
