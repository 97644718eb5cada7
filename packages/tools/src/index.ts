export { halTools } from './tools.js';
export type { AgentTool, HalTool, HalToolsOptions } from './tools.js';
export { toolBackedHal } from './tool-backed-hal.js';

export { STOP_TOOL, TOOL_CATALOG, toolCatalog } from './catalog.js';
export type { ToolEntry, ToolSafety } from './catalog.js';

export type { JsonSchemaObject } from './json-schema.js';
export { parseArguments } from './arguments.js';

export { toAnthropicTools, toJsonSchemas, toMcpTools, toOpenAITools } from './formats.js';
export type { AnthropicTool, McpTool, OpenAITool } from './formats.js';

export { createToolExecutor } from './executor.js';
export type { ToolCall, ToolExecutor, ToolExecutorOptions } from './executor.js';
export { errorResult } from './result.js';
export { REFUSAL_CODES } from './refusals.js';
export type { ToolContent, ToolResult } from './result.js';

export type { ApprovalDecision, Geofence, Leash } from './leash.js';

export { planMotion } from './motion-plan.js';
export type { MotionPlan, PlanStart } from './motion-plan.js';

export { callTimeoutMs, DEFAULT_TOOL_TIMEOUT_MS } from './timeouts.js';
export { robotConfigOf } from './robot-config.js';
