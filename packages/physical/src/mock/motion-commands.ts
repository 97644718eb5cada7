import type { MotionHandle } from '@hal/kinematics';
import type { ReplyDataOf } from '../protocol/schemas.js';
import { integerField, isAbsent, numberField } from './refusal.js';
import type { Json } from './refusal.js';
import type { RobotState } from './robot-state.js';

// The motion commands' wire fields, read as the firmware reads them (after its latch check), and
// handed to the robot model, which applies the firmware's rules and throws its refusals.

type MotionReplyData = ReplyDataOf<'move_steps'>;

function speedOf(r: Json): number | undefined {
  return isAbsent(r, 'speed') ? undefined : numberField(r, 'speed');
}

function moveReply({ report }: MotionHandle): MotionReplyData {
  return {
    move_id: report.moveId,
    left_steps: report.plannedLeft,
    right_steps: report.plannedRight,
    speed: report.speed,
    speed_clamped: report.speedClamped,
    duration_ms: Math.ceil(report.durationUs / 1000),
    duration_us: report.durationUs,
  };
}

/** `move_steps`: whole steps per wheel, not through the accumulators. */
export function moveSteps({ model }: RobotState, r: Json): MotionReplyData {
  model.refuseWhileLatched();
  const left = integerField(r, 'left');
  const right = integerField(r, 'right');
  return moveReply(model.moveSteps(left, right, speedOf(r)));
}

/** `move_cm`: each wheel's distance, through its accumulator. */
export function moveCm({ model }: RobotState, r: Json): MotionReplyData {
  model.refuseWhileLatched();
  const left = numberField(r, 'left_cm');
  const right = numberField(r, 'right_cm');
  return moveReply(model.moveCm(left, right, speedOf(r)));
}

/** `rotate_deg`: an in-place turn, counter-clockwise positive. */
export function rotateDeg({ model }: RobotState, r: Json): MotionReplyData {
  model.refuseWhileLatched();
  return moveReply(model.rotateDeg(numberField(r, 'degrees'), speedOf(r)));
}

/**
 * `drive`: wheel speeds, scaled together to the top speed when faster; both zero stops. Runs
 * until stopped, or for `duration_ms`.
 */
export function drive({ model }: RobotState, r: Json): MotionReplyData {
  model.refuseWhileLatched();
  const left = integerField(r, 'left_sps');
  const right = integerField(r, 'right_sps');
  const duration = isAbsent(r, 'duration_ms') ? undefined : integerField(r, 'duration_ms');
  const handle = model.drive(left, right, duration);
  return {
    move_id: model.motion?.moveId ?? 0,
    left_sps: handle?.report.leftSps ?? 0,
    right_sps: handle?.report.rightSps ?? 0,
    speed_clamped: handle?.report.speedClamped ?? false,
    ...(duration === undefined ? {} : { duration_ms: duration }),
    running: model.running,
  };
}
