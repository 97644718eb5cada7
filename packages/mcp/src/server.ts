import { Server } from '@modelcontextprotocol/sdk/server/index.js';
import {
  CallToolRequestSchema,
  ErrorCode,
  ListResourcesRequestSchema,
  ListToolsRequestSchema,
  McpError,
  ReadResourceRequestSchema,
  SubscribeRequestSchema,
  UnsubscribeRequestSchema,
} from '@modelcontextprotocol/sdk/types.js';
import { toMcpTools } from '@hal/tools';
import type { AgentTool, ToolCall, ToolResult } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { asks, DEFAULT_APPROVAL_TIMEOUT_MS, policyText } from './approval-policy.js';
import type { ApprovalPolicy } from './approval-policy.js';
import { eventsOf } from './events.js';
import type { RobotEvents, RobotEventSources } from './events.js';
import { serveLive } from './live.js';
import { DEFAULT_PROGRESS_PERIOD_MS } from './progress.js';
import { robotResources, stateOf } from './resources.js';
import type { RobotWorld } from './resources.js';
import { toolCalls } from './tool-calls.js';

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

/** How the server keeps a person in the loop and the client informed. */
export interface RobotMcpOptions {
  /**
   * Ask the client's user (MCP elicitation) before every motion (`'motion'`), before one longer
   * than `{ overM }` metres, or never (`'none'`, the default). The HAL calls are asked about by
   * the leash's approval hook: put `approveOverMcp` in the executor's leash. A skill that moves
   * is asked about once, by the server, before it starts.
   */
  approve?: ApprovalPolicy;
  /** How long the user has to answer, ms; unanswered is declined. Default 30000. */
  approvalTimeoutMs?: number;
  /** The robot's events; default the one feed of `monitor` every server of it shares. */
  events?: RobotEvents;
  /** Where that default feed reads events from besides the safety status (its first server's). */
  eventSources?: RobotEventSources;
  /** How often a motion's progress is read, ms. Default 200. */
  progressPeriodMs?: number;
  /**
   * The HAL the server watches for progress, state updates and events (default `hal`): the same
   * robot, given unwrapped so that a recording wrapper does not record every look.
   */
  monitor?: HardwareAbstractionLayer;
  /** How often robot://state is read for a subscriber, ms. Default 250. */
  statePeriodMs?: number;
}

/**
 * An MCP server for one HAL: its tools run through `offered` (an executor: validation, timeouts,
 * the leash; or a profile whose skills call such an executor), and its state, capabilities, map,
 * events and camera are resources. Each tool result goes back with its content and, as
 * `structuredContent`, its facts; refusals and failures with `isError`. Motions are approved by
 * the client's user as `options.approve` says, report progress to a client that asks, and
 * robot://state and robot://events can be subscribed to; the robot's log goes out as logging
 * notifications at the level the client sets. Connect it to a transport.
 */
export function createRobotMcpServer(
  hal: HardwareAbstractionLayer,
  offered: OfferedTools,
  world: RobotWorld = {},
  options: RobotMcpOptions = {},
): Server {
  const policy = options.approve ?? 'none';
  const monitor = options.monitor ?? hal;
  const events = options.events ?? eventsOf(monitor, options.eventSources);
  const server = new Server(SERVER_INFO, {
    capabilities: { tools: {}, resources: { subscribe: true }, logging: {} },
    instructions:
      'Drives a differential-drive robot. Frame REP-103: x forward, y left, yaw counter-clockwise ' +
      'positive; metres and radians unless a name says cm or degrees. Call emergency_stop whenever ' +
      'something looks wrong; it is always allowed.' +
      (asks(policy)
        ? ` A person approves motions (${policyText(policy)}): a declined one answers DENIED and nothing moves.`
        : ''),
  });
  const resources = () => robotResources(hal, offered.tools, world, events);
  const live = serveLive(server, events, policy, {
    statePeriodMs: options.statePeriodMs ?? 250,
    state: () => stateOf(monitor),
  });

  server.setRequestHandler(ListToolsRequestSchema, () => ({ tools: toMcpTools(offered.tools) }));
  server.setRequestHandler(
    CallToolRequestSchema,
    toolCalls({
      server,
      hal,
      monitor,
      offered,
      events,
      live,
      policy,
      approvalTimeoutMs: options.approvalTimeoutMs ?? DEFAULT_APPROVAL_TIMEOUT_MS,
      progressPeriodMs: options.progressPeriodMs ?? DEFAULT_PROGRESS_PERIOD_MS,
    }),
  );

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

  server.setRequestHandler(SubscribeRequestSchema, (request) => {
    live.subscribe(request.params.uri);
    return {};
  });
  server.setRequestHandler(UnsubscribeRequestSchema, (request) => {
    live.unsubscribe(request.params.uri);
    return {};
  });

  return server;
}
