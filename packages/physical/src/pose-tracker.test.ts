import { robotConfig } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { PoseTracker } from './pose-tracker.js';
import type { StatusReply } from './protocol/schemas.js';

/** A status reply of a robot at rest with the given counters. */
function status(left: number, right: number, uptimeMs = 1000): StatusReply {
  return {
    x_cm: 0,
    y_cm: 0,
    heading_rad: 0,
    left_steps: left,
    right_steps: right,
    running: false,
    move_id: 1,
    move_outcome: 'done',
    move_left_steps: 0,
    move_right_steps: 0,
    left_sps: 0,
    right_sps: 0,
    uptime_ms: uptimeMs,
    safety: {
      estop: false,
      estop_reason: '',
      trips: 0,
      host_timeout_ms: 2000,
      ms_since_host: 0,
      coils_on: false,
    },
    led: { r: 0, g: 0, b: 0, pattern: 'off' },
  };
}

/** A tracker on a hand-moved clock (ms), the robot at the origin, heard from at t = 0. */
function tracker(hostTimeoutMs = 2000) {
  let now = 0;
  const t = new PoseTracker(robotConfig({ hostTimeoutMs }), () => now, 1);
  t.anchor(status(0, 0));
  return { t, advance: (ms: number) => void (now += ms) };
}

/** An endless straight drive at full speed (1024 steps/s), as a `drive` reply reports it. */
const drive = { move_id: 2, left_sps: 1024, right_sps: 1024, running: true };

describe('PoseTracker', () => {
  it('confirms the pose of a robot at rest that last reported it', () => {
    const { t } = tracker();
    expect(t.pose()).toMatchObject({ position: { x: 0, y: 0 }, confirmed: true });
  });

  it('reports the counters the robot sent, not the prediction, and nothing before a status', () => {
    const fresh = new PoseTracker(robotConfig(), () => 0, 1);
    expect(fresh.reported()).toBeUndefined();
    const { t, advance } = tracker();
    t.observe('drive', drive);
    advance(500);
    // the pose is predicted half a second along, but the robot has reported nothing since
    expect(t.pose().position.x).toBeGreaterThan(0);
    expect(t.reported()).toEqual({
      leftSteps: 0,
      rightSteps: 0,
      leftStepsPerS: 0,
      rightStepsPerS: 0,
      robotUptimeMs: 1000,
    });
    t.observe('get_status', {
      ...status(300, 310, 1500),
      running: true,
      left_sps: 900,
      right_sps: 905,
    });
    expect(t.reported()).toEqual({
      leftSteps: 300,
      rightSteps: 310,
      leftStepsPerS: 900,
      rightStepsPerS: 905,
      robotUptimeMs: 1500,
    });
  });

  it('marks the pose predicted while a motion runs, and confirmed once a stop reports it', () => {
    const { t, advance } = tracker();
    t.observe('drive', drive);
    advance(500);
    const moving = t.pose();
    expect(moving.position.x).toBeGreaterThan(0);
    expect(moving.confirmed).toBe(false);
    t.observe('stop', { left_steps: 400, right_steps: 400, stopped: true });
    expect(t.pose().confirmed).toBe(true);
  });

  it('never predicts past the host timeout after the robot was last heard from', () => {
    const { t, advance } = tracker(2000);
    t.observe('drive', drive);
    advance(1000);
    t.observe('heartbeat', {});
    advance(2000);
    const atTimeout = t.pose().position.x;
    // heard at 1 s: a robot that heard nothing more stopped by 3 s at the latest
    advance(5000);
    const later = t.pose();
    expect(later.position.x).toBe(atTimeout);
    expect(later.velocity.linear).toBe(0);
    expect(later.confirmed).toBe(false);
    // 3 s at up to 1024 steps/s (217.3 steps/cm) is at most 14.1 cm
    expect(later.position.x).toBeLessThan(0.142);
  });

  it('marks even a pose at rest unconfirmed while the link is lost', () => {
    const { t } = tracker();
    t.linkChanged(false);
    expect(t.pose().confirmed).toBe(false);
    t.linkChanged(true);
    expect(t.pose().confirmed).toBe(true);
  });
});
