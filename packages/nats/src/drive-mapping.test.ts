import { HalError, V1_ROBOT, maxLinearSpeedMPerS } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { wheelPowersFor, wheelVelocities } from './drive-mapping.js';

const cmd = (v: number, w: number) => ({ linear_vel_m_per_s: v, angular_vel_rad_per_s: w });
const top = maxLinearSpeedMPerS(V1_ROBOT);

describe('wheelPowersFor', () => {
  it('maps the top linear speed to full power on both wheels', () => {
    expect(wheelPowersFor(cmd(top, 0), V1_ROBOT)).toEqual({ left: 255, right: 255 });
    expect(wheelPowersFor(cmd(-top / 2, 0), V1_ROBOT)).toEqual({ left: -127, right: -127 });
  });

  it('turns counter-clockwise for a positive angular velocity (REP-103): right wheel forward', () => {
    const w = top / (V1_ROBOT.wheelBaseCm / 200);
    expect(wheelPowersFor(cmd(0, w), V1_ROBOT)).toEqual({ left: -255, right: 255 });
  });

  it('refuses a command that needs a wheel beyond the top speed with RANGE_EXCEEDED', () => {
    expect(() => wheelPowersFor(cmd(top, 0.5), V1_ROBOT)).toThrow(HalError);
    expect(() => wheelPowersFor(cmd(1, 0), V1_ROBOT)).toThrow(/top wheel speed/);
  });

  it('refuses NaN and infinite velocities with INVALID_PARAMETER naming the field', () => {
    expect(() => wheelPowersFor(cmd(Number.NaN, 0), V1_ROBOT)).toThrow(/"linear_vel_m_per_s"/);
    expect(() => wheelPowersFor(cmd(0, Infinity), V1_ROBOT)).toThrow(/"angular_vel_rad_per_s"/);
  });
});

describe('wheelVelocities', () => {
  it('splits a body velocity into wheel ground speeds, the inverse of the mapping', () => {
    expect(wheelVelocities(0.02, 0.2, V1_ROBOT)).toEqual({
      left_vel_m_per_s: 0.02 - 0.2 * 0.05,
      right_vel_m_per_s: 0.02 + 0.2 * 0.05,
    });
  });
});
