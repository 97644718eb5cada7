export { createRobotMcpServer, SERVER_INFO } from './server.js';
export { robotResources } from './resources.js';
export type { RobotResource, RobotWorld } from './resources.js';
export { isLoopback, serveHttp } from './http.js';
export type { HttpEndpoint, HttpOptions } from './http.js';
