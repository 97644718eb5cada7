// The server's answer to tools/call: the call runs through the tools offered inside its own
// context (so the leash's approval hook can ask this call's client), a skill that moves is asked
// about first, a motion reports its progress to a client that asked, and a stop withdraws the
// questions still open.
import type { Server } from '@modelcontextprotocol/sdk/server/index.js';
import type { RequestHandlerExtra } from '@modelcontextprotocol/sdk/shared/protocol.js';
import type {
  CallToolRequest,
  CallToolResult,
  ServerNotification,
  ServerRequest,
} from '@modelcontextprotocol/sdk/types.js';
import { errorResult, robotConfigOf } from '@hal/tools';
import type { AgentTool, ToolCall, ToolResult } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { decide } from './approval.js';
import type { Summarize } from './motion-words.js';
import type { ApprovalPolicy } from './approval-policy.js';
import { inCall } from './call-context.js';
import type { CallContext } from './call-context.js';
import { elicitApproval } from './elicit.js';
import type { RobotEvents } from './events.js';
import type { Live } from './live.js';
import { summarizeMotion } from './motion-words.js';
import { watchProgress } from './progress.js';
import type { ProgressWatch } from './progress.js';

/** What answering tool calls needs. */
export interface ToolCallDeps {
  server: Server;
  /** The robot the tools drive (limits). */
  hal: HardwareAbstractionLayer;
  /** The same robot, watched for poses (progress, the start of a motion asked about). */
  monitor: HardwareAbstractionLayer;
  offered: {
    readonly tools: readonly AgentTool[];
    execute(call: ToolCall): Promise<ToolResult>;
  };
  events: RobotEvents;
  live: Live;
  policy: ApprovalPolicy;
  approvalTimeoutMs: number;
  progressPeriodMs: number;
}

const isHalTool = (tool: AgentTool) => typeof (tool as { call?: unknown }).call === 'string';

const argsOf = (raw: unknown): Record<string, unknown> =>
  typeof raw === 'object' && raw !== null && !Array.isArray(raw)
    ? (raw as Record<string, unknown>)
    : {};

/** The tools/call handler of one server. */
export function toolCalls(deps: ToolCallDeps) {
  const { server, hal, monitor, offered, events, live, policy } = deps;

  const summarize: Summarize = async (tool, args) => {
    try {
      const pose = await monitor.locomotion.getPose();
      const start = { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
      return summarizeMotion(tool, args, start, robotConfigOf(hal));
    } catch {
      // no pose: ask about it as one whose length is not known
      return tool.motion
        ? {
            words: `run ${tool.name} ${JSON.stringify(args)}`,
            distanceM: undefined,
            progress: { unit: 'm' as const },
          }
        : undefined;
    }
  };

  const progressOf = async (
    tool: AgentTool | undefined,
    args: Record<string, unknown>,
    request: CallToolRequest,
    extra: RequestHandlerExtra<ServerRequest, ServerNotification>,
  ): Promise<ProgressWatch | undefined> => {
    const token = request.params._meta?.progressToken;
    if (token === undefined || tool?.motion !== true) return undefined;
    const summary = await summarize(tool, args);
    if (summary === undefined) return undefined;
    return watchProgress(
      monitor,
      summary,
      (report) =>
        extra.sendNotification({
          method: 'notifications/progress',
          params: { progressToken: token, ...report },
        }),
      deps.progressPeriodMs,
    );
  };

  return async (
    request: CallToolRequest,
    extra: RequestHandlerExtra<ServerRequest, ServerNotification>,
  ): Promise<CallToolResult> => {
    const { name } = request.params;
    const args = argsOf(request.params.arguments);
    const tool = offered.tools.find((t) => t.name === name);
    // a stop withdraws the questions open (in every session): what was asked about before it
    // does not run after it
    if (tool?.safety !== undefined) events.stopped();
    if (tool?.safety === 'estop') events.expect('estop');
    if (name === 'reset_emergency_stop') events.expect('reset');
    const context: CallContext = {
      tool: name,
      policy,
      ask: elicitApproval(server, extra, deps.approvalTimeoutMs, () => events.nextStop()),
      summarize,
      approved: false,
      hookConsulted: false,
    };
    const watch = await progressOf(tool, args, request, extra);
    const result = await inCall(context, async () => {
      // a skill makes HAL calls of its own: the user approves it once, here, before it starts
      if (tool !== undefined && !isHalTool(tool)) {
        const decision = await decide(context, tool, args, summarize);
        if (!decision.allow) return errorResult('DENIED', `${name}: denied: ${decision.reason}`);
      }
      return offered.execute({ name, arguments: request.params.arguments });
    });
    await watch?.finish(!result.isError);
    if (tool?.safety !== undefined || name === 'reset_emergency_stop') events.check();
    if (tool !== undefined && isHalTool(tool) && tool.motion && !result.isError) {
      live.checkHooked(context);
    }
    return {
      content: result.content,
      isError: result.isError,
      ...(result.structured === undefined ? {} : { structuredContent: result.structured }),
    };
  };
}
