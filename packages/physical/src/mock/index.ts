// @hal/physical/testing: an in-process robot that speaks protocol 1.1, for tests without hardware:
// `new PhysicalHAL(config, { transport: robot.transport() })`.
export { MockRobot } from './mock-robot.js';
export type { MockRobotOptions } from './mock-robot.js';
export type { MockTransportOptions } from './mock-transport.js';
