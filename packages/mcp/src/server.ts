import { Server } from '@modelcontextprotocol/sdk/server/index.js';
import {
  CallToolRequestSchema,
  ErrorCode,
  ListResourcesRequestSchema,
  ListToolsRequestSchema,
  McpError,
  ReadResourceRequestSchema,
} from '@modelcontextprotocol/sdk/types.js';
import { toMcpTools } from '@hal/tools';
import type { AgentTool, ToolCall, ToolResult } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { robotResources } from './resources.js';
import type { RobotWorld } from './resources.js';

/** The server's name and version, as MCP clients show them. */
export const SERVER_INFO = { name: 'hal-robot', version: '0.1.0' } as const;

/**
 * The tools a server offers and how it runs them: a `ToolExecutor` of @hal/tools (the HAL's calls),
 * or a tool profile of @hal/skills (the skills, or both). `execute` never throws.
 */
export interface OfferedTools {
  readonly tools: readonly AgentTool[];
  execute(call: ToolCall): Promise<ToolResult>;
}

/**
 * An MCP server for one HAL: its tools run through `offered` (an executor: validation, timeouts,
 * the leash; or a profile whose skills call such an executor), and its state, capabilities, map
 * and camera are resources. Each tool result goes back with its content and, as
 * `structuredContent`, its facts; refusals and failures with `isError`. Connect it to a transport.
 */
export function createRobotMcpServer(
  hal: HardwareAbstractionLayer,
  offered: OfferedTools,
  world: RobotWorld = {},
): Server {
  const server = new Server(SERVER_INFO, {
    capabilities: { tools: {}, resources: {} },
    instructions:
      'Drives a differential-drive robot. Frame REP-103: x forward, y left, yaw counter-clockwise ' +
      'positive; metres and radians unless a name says cm or degrees. Call emergency_stop whenever ' +
      'something looks wrong; it is always allowed.',
  });
  const resources = () => robotResources(hal, offered.tools, world);

  server.setRequestHandler(ListToolsRequestSchema, () => ({ tools: toMcpTools(offered.tools) }));

  server.setRequestHandler(CallToolRequestSchema, async (request) => {
    const result = await offered.execute({
      name: request.params.name,
      arguments: request.params.arguments,
    });
    return {
      content: result.content,
      isError: result.isError,
      ...(result.structured === undefined ? {} : { structuredContent: result.structured }),
    };
  });

  server.setRequestHandler(ListResourcesRequestSchema, () => ({
    resources: resources().map(({ uri, name, description, mimeType }) => ({
      uri,
      name,
      description,
      mimeType,
    })),
  }));

  server.setRequestHandler(ReadResourceRequestSchema, async (request) => {
    const resource = resources().find((r) => r.uri === request.params.uri);
    if (resource === undefined) {
      throw new McpError(ErrorCode.InvalidParams, `no resource ${request.params.uri}`);
    }
    const body = await resource.read();
    return { contents: [{ uri: resource.uri, mimeType: resource.mimeType, ...body }] };
  });

  return server;
}
