// One way to print a pose for people: metres, degrees (REP-103: yaw counter-clockwise positive).
// A pose the robot has not confirmed (the host's prediction) says so: it is never shown as measured.
import type { Pose } from '@hal/types';

const RAD_TO_DEG = 180 / Math.PI;

/**
 * `x 0.050 m  y 0.000 m  yaw 90.0°`, with the velocities when `velocity` is true, and
 * `  predicted` after it when the HAL marks the pose unconfirmed.
 */
export function poseText(pose: Pose, velocity = false): string {
  let text =
    `x ${pose.position.x.toFixed(3)} m  y ${pose.position.y.toFixed(3)} m  ` +
    `yaw ${(pose.rotation.yaw * RAD_TO_DEG).toFixed(1)}°`;
  if (velocity) {
    text += `  v ${pose.velocity.linear.toFixed(3)} m/s  ω ${pose.velocity.angular.toFixed(2)} rad/s`;
  }
  return pose.confirmed === false ? `${text}  predicted` : text;
}
