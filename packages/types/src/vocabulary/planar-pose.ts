/**
 * A pose on the floor in the REP-103 frame, in the HAL's units: x forward and y left in metres,
 * yaw counter-clockwise in radians. The planar part of a {@link Pose}.
 */
export interface PlanarPose {
  x: number;
  y: number;
  yaw: number;
}
