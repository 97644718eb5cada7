import { getStepsPerCm, V1_GEOMETRY } from '@hal/kinematics';
import { describe, expect, it } from 'vitest';
import { BodyPose } from './body-pose.js';

const perCm = getStepsPerCm(V1_GEOMETRY);

describe('BodyPose', () => {
  it("moves the body from the world's start along its heading by the steps both wheels made", () => {
    const body = new BodyPose({ x: 1, y: -0.5, yaw: Math.PI / 2 });
    body.update({ left: Math.round(20 * perCm), right: Math.round(20 * perCm) });
    expect(body.pose.x).toBeCloseTo(1, 4);
    expect(body.pose.y).toBeCloseTo(-0.3, 3);
    expect(body.pose.yaw).toBeCloseTo(Math.PI / 2, 9);
  });

  it('turns in place when the wheels turn opposite ways, counting from the positions it started at', () => {
    // a quarter turn: each wheel travels a quarter of the wheel base's circle
    const arc = Math.round(((Math.PI * V1_GEOMETRY.wheelBaseCm) / 4) * perCm);
    const body = new BodyPose({ x: 0, y: 0, yaw: 0 }, V1_GEOMETRY, { left: 5000, right: 7000 });
    body.update({ left: 5000 - arc, right: 7000 + arc });
    expect(body.pose.yaw).toBeCloseTo(Math.PI / 2, 3);
    expect(Math.hypot(body.pose.x, body.pose.y)).toBeLessThan(1e-9);
  });
});
