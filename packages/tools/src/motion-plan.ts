import { HAL_CALL_TABLE, findCall, maxLinearSpeedMPerS, stepsPerCm } from '@hal/types';
import type { CallTable, RobotConfig } from '@hal/types';

/** Where a motion starts: metres and radians, REP-103 world frame. */
export interface PlanStart {
  x: number;
  y: number;
  yaw: number;
}

/** What a motion call will do, predicted from its arguments and the start pose. */
export interface MotionPlan {
  /** Path length, metres (Infinity: a drive with no duration). */
  distanceM: number;
  /** The fastest a wheel will go, m/s (0 for a turn in place, which does not travel). */
  speedMPerS: number;
  /** Points along the path, the end last (undefined: the end cannot be predicted). */
  path: Array<{ x: number; y: number }> | undefined;
  /** How long the motion profile takes, ms (Infinity when unbounded). */
  durationMs: number;
}

/** Duration of a trapezoidal move of `steps` at top speed `v` steps/s and acceleration `a`. */
function profileMs(steps: number, v: number, a: number): number {
  const s = Math.abs(steps);
  const seconds = s >= (v * v) / a ? s / v + v / a : 2 * Math.sqrt(s / a);
  return seconds * 1000;
}

function straight(start: PlanStart, metres: number, config: RobotConfig): MotionPlan {
  const steps = metres * 100 * stepsPerCm(config);
  const end = {
    x: start.x + metres * Math.cos(start.yaw),
    y: start.y + metres * Math.sin(start.yaw),
  };
  return {
    distanceM: Math.abs(metres),
    speedMPerS: maxLinearSpeedMPerS(config),
    path: [end],
    durationMs: profileMs(steps, config.maxSpeedStepsPerS, config.accelerationStepsPerS2),
  };
}

/** Samples the arc of a drive at constant wheel speeds (metres per second per wheel). */
function arc(start: PlanStart, vl: number, vr: number, seconds: number, config: RobotConfig) {
  const base = config.wheelBaseCm / 100;
  const samples = 24;
  const path: Array<{ x: number; y: number }> = [];
  let { x, y, yaw } = start;
  const dt = seconds / samples;
  for (let i = 0; i < samples; i++) {
    const v = (vl + vr) / 2;
    x += v * Math.cos(yaw) * dt;
    y += v * Math.sin(yaw) * dt;
    yaw += ((vr - vl) / base) * dt;
    path.push({ x, y });
  }
  return path;
}

/**
 * Predicts a motion call's path, speed and duration from validated arguments, by what the call
 * does (its `motion` in `table`). The robot's own profile: straight drives and turns run at its
 * top speed, a drive to a point at `speed` (default top), the wheels at power / 255 of top speed
 * for `durationMs`. Undefined for a call that is no motion.
 */
export function planMotion(
  call: string,
  args: Record<string, unknown>,
  start: PlanStart,
  config: RobotConfig,
  table: CallTable = HAL_CALL_TABLE,
): MotionPlan | undefined {
  const top = maxLinearSpeedMPerS(config);
  const accel = config.accelerationStepsPerS2;
  const spc = stepsPerCm(config);
  const turnMs = (radians: number) =>
    profileMs(
      ((Math.abs(radians) * config.wheelBaseCm) / 2) * spc,
      config.maxSpeedStepsPerS,
      accel,
    );
  switch (findCall(call, table)?.motion) {
    case 'forward':
      return straight(start, (args['distanceCm'] as number) / 100, config);
    case 'backward':
      return straight(start, -(args['distanceCm'] as number) / 100, config);
    case 'turn':
      return {
        distanceM: 0,
        speedMPerS: 0,
        path: [{ x: start.x, y: start.y }],
        durationMs: turnMs(((args['degrees'] as number) * Math.PI) / 180),
      };
    case 'point': {
      const x = args['x'] as number;
      const y = args['y'] as number;
      const speed = (args['speed'] as number | undefined) ?? top;
      const distanceM = Math.hypot(x - start.x, y - start.y);
      const steps = distanceM * 100 * spc;
      const speedSteps = speed * 100 * spc;
      return {
        distanceM,
        speedMPerS: speed,
        path: [{ x, y }],
        durationMs: turnMs(Math.PI) + profileMs(steps, speedSteps, accel),
      };
    }
    case 'wheels': {
      const vl = ((args['left'] as number) / 255) * top;
      const vr = ((args['right'] as number) / 255) * top;
      const speedMPerS = Math.max(Math.abs(vl), Math.abs(vr));
      const durationMs = args['durationMs'] as number | undefined;
      if (durationMs === undefined) {
        return { distanceM: Infinity, speedMPerS, path: undefined, durationMs: Infinity };
      }
      const seconds = durationMs / 1000;
      return {
        distanceM: (Math.abs(vl + vr) / 2) * seconds,
        speedMPerS,
        path: arc(start, vl, vr, seconds, config),
        durationMs,
      };
    }
    case undefined:
      return undefined;
  }
}
