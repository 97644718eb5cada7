export { RobotHAL } from './robot-hal/robot-hal.js';
export {
  MAX_POWER,
  groundSpeedToStepsPerS,
  poseData,
  powerToStepsPerS,
} from './robot-hal/locomotion.js';
export { KEPT_LOGS } from './robot-hal/communication.js';
