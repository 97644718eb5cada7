export { getStepsPerCm, V1_GEOMETRY } from './geometry.js';
export type { MotionLimits, RobotGeometry } from './geometry.js';
export { distanceToSteps, rotationArcCm, rotationToSteps, StepAccumulator } from './steps.js';
export type { WheelPair } from './steps.js';
export { TrapezoidalProfile, VelocityProfile } from './profile.js';
export { MovePlan, VelocityPlan } from './planner.js';
export type { StepPlan } from './planner.js';
export { integrateOdometry, OdometryIntegrator } from './odometry.js';
export type { PlanarPoseCm } from './odometry.js';
export { RobotModel } from './robot-model/robot-model.js';
export type { RobotModelOptions } from './robot-model/robot-model.js';
export type { MotionHandle, MotionReport, MoveOutcome } from './robot-model/motion-report.js';
export type { SafetyTrip } from './robot-model/robot-safety.js';
export { checkSetting, FIRMWARE_SETTINGS } from './robot-model/settings.js';
export type { FirmwareSetting, FirmwareSettingKey } from './robot-model/settings.js';
export type { BodyScales, MotionScales, WheelScale } from './robot-model/wheel-scale.js';
export { blockingContact, NOTHING_TO_TOUCH } from './robot-model/step-contact.js';
export type {
  ContactTest,
  FreeSpace,
  FreeSpaceTest,
  StepContact,
} from './robot-model/step-contact.js';
export {
  cameraProjection,
  floorPointOfPixel,
  horizonRow,
  nearestVisibleFloorM,
  pixelOfPoint,
  pixelRay,
} from './camera.js';
export type { CameraProjection, FloorPoint, ImagePoint, Vec3 } from './camera.js';
