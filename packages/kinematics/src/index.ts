export { getStepsPerCm, PI, V1_GEOMETRY, wheelCircumferenceCm } from './geometry.js';
export type { MotionLimits, RobotGeometry } from './geometry.js';
export {
  calculateArcSpeeds,
  distanceToSteps,
  exactStepsForDistance,
  rotationArcCm,
  rotationToSteps,
  StepAccumulator,
  stepsToDistance,
  truncateSteps,
  velocityToStepsPerSecond,
} from './steps.js';
export type { WheelPair } from './steps.js';
export { calculateMoveDuration, toMicros, TrapezoidalProfile, VelocityProfile } from './profile.js';
export { MovePlan, VelocityPlan } from './planner.js';
export type { StepPlan } from './planner.js';
export { integrateOdometry, OdometryIntegrator } from './odometry.js';
export type { PlanarPoseCm } from './odometry.js';
