export { createRobotMcpServer, SERVER_INFO } from './server.js';
export { robotResources } from './resources.js';
export type { RobotResource, RobotWorld } from './resources.js';
export { isLoopback, serveHttp } from './http.js';
export type { HttpEndpoint, HttpOptions } from './http.js';
export { createRobot } from './robot.js';
export type { RobotTarget } from './robot.js';
export { parseCli, runCli } from './cli.js';
export type { CliOptions } from './cli.js';
