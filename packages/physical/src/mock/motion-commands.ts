import { MovePlan, rotationArcCm, VelocityPlan } from '@hal/kinematics';
import { deviceGeometry, MAX_STEPS_PER_COMMAND } from '../protocol/device-config.js';
import type { ReplyDataOf } from '../protocol/schemas.js';
import { integerField, isAbsent, numberField, Refusal } from './refusal.js';
import type { Json } from './refusal.js';
import { emergencyStop } from './robot-state.js';
import type { RobotState } from './robot-state.js';

type MotionReplyData = ReplyDataOf<'move_steps'>;

/** The cruise speed of a motion command: absent means the top speed; clamped into 1..top. */
function speedOf(state: RobotState, r: Json): { speed: number; clamped: boolean } {
  const max = state.settings.max_speed_steps_per_s;
  if (isAbsent(r, 'speed')) return { speed: max, clamped: false };
  const speed = numberField(r, 'speed');
  if (speed <= 0)
    throw new Refusal('RANGE_EXCEEDED', `"speed" must be 1..${max} steps/s`, {
      field: 'speed',
      min: 1,
      max,
      value: speed,
    });
  if (speed > max) return { speed: max, clamped: true };
  if (speed < 1) return { speed: 1, clamped: true };
  return { speed, clamped: false };
}

/**
 * Starts a move of whole steps on each wheel. More than the step limit on either wheel is refused
 * RANGE_EXCEEDED and trips the e-stop, as the firmware does.
 */
function startMove(state: RobotState, left: number, right: number, r: Json): MotionReplyData {
  state.safety.refuseWhileLatched();
  for (const [field, steps] of [
    ['left', left],
    ['right', right],
  ] as const) {
    if (Math.abs(steps) > MAX_STEPS_PER_COMMAND) {
      emergencyStop(state, `step limit: "${field}" ${steps} steps`, {
        reason: 'step_limit',
        detail: `${field} ${steps}`,
      });
      throw new Refusal(
        'RANGE_EXCEEDED',
        `"${field}" gives ${steps} steps; the limit is ${MAX_STEPS_PER_COMMAND} steps per command (emergency stop latched)`,
        {
          field,
          min: -MAX_STEPS_PER_COMMAND,
          max: MAX_STEPS_PER_COMMAND,
          value: steps,
          estop: true,
        },
      );
    }
  }
  const { speed, clamped } = speedOf(state, r);
  const plan = new MovePlan(left, right, speed, state.settings.acceleration_steps_per_s2);
  state.motion.begin(plan, plan.durationUs);
  return {
    move_id: state.motion.moveId,
    left_steps: left,
    right_steps: right,
    speed,
    speed_clamped: clamped,
    duration_ms: Math.ceil(plan.durationUs / 1000),
    duration_us: plan.durationUs,
  };
}

/** `move_steps`: whole steps per wheel, not through the accumulators. */
export function moveSteps(state: RobotState, r: Json): MotionReplyData {
  return startMove(state, integerField(r, 'left'), integerField(r, 'right'), r);
}

/** `move_cm`: each wheel's distance, through its accumulator. */
export function moveCm(state: RobotState, r: Json): MotionReplyData {
  state.safety.refuseWhileLatched();
  const left = state.motion.addCm('left', numberField(r, 'left_cm'));
  const right = state.motion.addCm('right', numberField(r, 'right_cm'));
  return startMove(state, left, right, r);
}

/** `rotate_deg`: an in-place turn, counter-clockwise positive. */
export function rotateDeg(state: RobotState, r: Json): MotionReplyData {
  state.safety.refuseWhileLatched();
  const arc = rotationArcCm(numberField(r, 'degrees'), deviceGeometry(state.settings));
  const left = state.motion.addCm('left', -arc);
  const right = state.motion.addCm('right', arc);
  return startMove(state, left, right, r);
}

/**
 * `drive`: wheel speeds, scaled together to the top speed when faster; both zero stops. Runs
 * until stopped, or for `duration_ms`.
 */
export function drive(state: RobotState, r: Json): MotionReplyData {
  state.safety.refuseWhileLatched();
  let left = integerField(r, 'left_sps');
  let right = integerField(r, 'right_sps');
  const duration = isAbsent(r, 'duration_ms') ? undefined : integerField(r, 'duration_ms');
  const max = state.settings.max_speed_steps_per_s;
  const fastest = Math.max(Math.abs(left), Math.abs(right));
  const clamped = fastest > max;
  if (clamped) {
    left = Math.trunc((left * max) / fastest);
    right = Math.trunc((right * max) / fastest);
  }
  const reply = {
    left_sps: left,
    right_sps: right,
    speed_clamped: clamped,
    ...(duration === undefined ? {} : { duration_ms: duration }),
  };
  if (left === 0 && right === 0) {
    state.motion.stop('stopped');
    return { move_id: state.motion.moveId, ...reply, running: false };
  }
  const plan = new VelocityPlan(left, right, state.settings.acceleration_steps_per_s2);
  state.motion.begin(plan, duration === undefined ? Number.POSITIVE_INFINITY : duration * 1000);
  return { move_id: state.motion.moveId, ...reply, running: true };
}
