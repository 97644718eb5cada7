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
import type { ToolExecutor } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { robotResources } from './resources.js';
import type { RobotWorld } from './resources.js';

/** The server's name and version, as MCP clients show them. */
export const SERVER_INFO = { name: 'hal-robot', version: '0.1.0' } as const;

/**
 * An MCP server for one HAL: its tools run through `executor` (validation, timeouts, the leash),
 * and its state, capabilities, map and camera are resources. Connect it to a transport.
 */
export function createRobotMcpServer(
  hal: HardwareAbstractionLayer,
  executor: ToolExecutor,
  world: RobotWorld = {},
): Server {
  const server = new Server(SERVER_INFO, {
    capabilities: { tools: {}, resources: {} },
    instructions:
      'Drives a differential-drive robot. Frame REP-103: x forward, y left, yaw counter-clockwise ' +
      'positive; metres and radians unless a name says cm or degrees. Call emergency_stop whenever ' +
      'something looks wrong; it is always allowed.',
  });
  const resources = () => robotResources(hal, executor.tools, world);

  server.setRequestHandler(ListToolsRequestSchema, () => ({ tools: toMcpTools(executor.tools) }));

  server.setRequestHandler(CallToolRequestSchema, async (request) => {
    const result = await executor.execute({
      name: request.params.name,
      arguments: request.params.arguments,
    });
    return { content: result.content, isError: result.isError };
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
