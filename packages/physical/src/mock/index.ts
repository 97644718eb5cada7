// @hal/physical/testing: a robot that speaks protocol 1.1, for tests without hardware: in the
// process (`new PhysicalHAL(config, { transport: robot.transport() })`) or on a real UDP socket
// (`new PhysicalHAL({ ..., connection: (await MockUdpRobot.start()).connection })`).
export { MockRobot } from './mock-robot.js';
export type { MockRobotOptions } from './mock-robot.js';
export { MockUdpRobot } from './udp-robot.js';
export type { MockUdpConnection, MockUdpRobotOptions } from './udp-robot.js';
export type { MockTransportOptions } from './mock-transport.js';
// The request/reply session under PhysicalHAL, for measuring its layers apart (bench/udp-layers.ts).
export { Session } from '../session.js';
export type { SessionOptions } from '../session-options.js';
