// @hal/mcp: the MCP server for any HAL (`hal mcp` of @hal/cli builds the HAL and runs it).
export { createRobotMcpServer } from './server.js';
export type { OfferedTools } from './server.js';
export type { RobotWorld } from './resources.js';
export { serveHttp } from './http.js';
export type { HttpEndpoint, HttpOptions } from './http.js';
