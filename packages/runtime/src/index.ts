export { RobotHAL } from './robot-hal/robot-hal.js';
export {
  MAX_POWER,
  groundSpeedToStepsPerS,
  poseData,
  powerToStepsPerS,
} from './robot-hal/locomotion.js';
export { KEPT_LOGS } from './robot-hal/communication.js';

// The base of the HALs that forward their calls over a link (RemoteHAL, NatsHAL).
export { ForwardingHAL } from './forwarding/forwarding-hal.js';
export type {
  ForwardingHALOptions,
  HostLatchPolicy,
  SendOptions,
} from './forwarding/forwarding-hal.js';

// The server side shared by every server of a HAL (WebSocket, NATS).
export { browserRefusal, hostOfHeader, isLoopback, trustedOrigin } from './serving/browser-gate.js';
export type { BrowserRefusal, GateHeaders } from './serving/browser-gate.js';
export { ControllerWatch } from './serving/controller-watch.js';
export type { ControllerWatchOptions } from './serving/controller-watch.js';
export { ServedCalls } from './serving/served-calls.js';
export type { ServedCallsOptions } from './serving/served-calls.js';
