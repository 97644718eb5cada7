// @hal/mcp: the MCP server for any HAL (`hal mcp` of @hal/cli builds the HAL and runs it).
export { createRobotMcpServer } from './server.js';
export type { OfferedTools, RobotMcpOptions } from './server.js';
export type { RobotWorld } from './resources.js';
export { serveHttp } from './http.js';
export type { HttpEndpoint, HttpOptions } from './http.js';
export { approveOverMcp } from './approval.js';
export { DEFAULT_APPROVAL_TIMEOUT_MS, parseApprovalPolicy, policyText } from './approval-policy.js';
export type { ApprovalPolicy } from './approval-policy.js';
export { eventsOf, RobotEvents } from './events.js';
export type {
  GuardEventLike,
  RobotEvent,
  RobotEventSources,
  RobotEventsOptions,
  RobotEventType,
  RobotLogLine,
} from './events.js';
