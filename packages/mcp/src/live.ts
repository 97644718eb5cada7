// What a connected client is told without asking: updates of the resources it subscribed to
// (robot://state when it changes, robot://events when one happens) and the robot's log as
// logging notifications (the SDK drops those below the level the client set). All of it starts
// once the client has initialized and ends when the connection closes.
import type { Server } from '@modelcontextprotocol/sdk/server/index.js';
import { ErrorCode, McpError } from '@modelcontextprotocol/sdk/types.js';
import type { LoggingLevel } from '@modelcontextprotocol/sdk/types.js';
import type { LogLevel } from '@hal/types';
import { asks, policyText } from './approval-policy.js';
import type { ApprovalPolicy } from './approval-policy.js';
import type { CallContext } from './call-context.js';
import { canElicit } from './elicit.js';
import type { RobotEvents, RobotLogLine } from './events.js';
import { EVENTS_URI, STATE_URI } from './resources.js';

const MCP_LEVEL: Record<LogLevel, LoggingLevel> = {
  debug: 'debug',
  info: 'info',
  warn: 'warning',
  error: 'error',
};

const SUBSCRIBABLE = new Set([STATE_URI, EVENTS_URI]);

/** A server's live side. */
export interface Live {
  subscribe(uri: string): void;
  unsubscribe(uri: string): void;
  /** After a HAL motion ran: says once if the approval hook was not in the executor's leash. */
  checkHooked(context: CallContext): void;
}

export function serveLive(
  server: Server,
  events: RobotEvents,
  policy: ApprovalPolicy,
  options: {
    statePeriodMs: number;
    /** Reads the robot's state, as robot://state holds it. */
    state: () => Promise<unknown>;
  },
): Live {
  const subscribed = new Set<string>();
  const stops: Array<() => void> = [];
  let stateTimer: ReturnType<typeof setInterval> | undefined;
  let warnedUnhooked = false;

  const log = (line: RobotLogLine) => {
    server
      .sendLoggingMessage({ level: MCP_LEVEL[line.level], logger: line.logger, data: line.message })
      .catch(() => undefined);
  };
  const updated = (uri: string) => {
    if (subscribed.has(uri)) server.sendResourceUpdated({ uri }).catch(() => undefined);
  };
  const stateText = async () => {
    try {
      return JSON.stringify(await options.state());
    } catch {
      return undefined;
    }
  };

  server.oninitialized = () => {
    stops.push(events.open());
    stops.push(events.on(() => updated(EVENTS_URI)));
    stops.push(events.onLog(log));
    if (policy === 'none') {
      log({
        level: 'info',
        logger: 'mcp',
        message: 'No one approves motions: they run as the leash allows (approval: none)',
      });
    } else if (!canElicit(server)) {
      log({
        level: 'error',
        logger: 'mcp',
        message:
          `This server asks before motions (approval: ${policyText(policy)}) and this client did ` +
          'not declare elicitation: every motion will be refused (DENIED) until a client that ' +
          'can answer connects',
      });
    }
  };

  server.onclose = () => {
    if (stateTimer !== undefined) clearInterval(stateTimer);
    stateTimer = undefined;
    for (const stop of stops.splice(0)) stop();
    subscribed.clear();
  };

  return {
    subscribe(uri) {
      if (!SUBSCRIBABLE.has(uri)) {
        throw new McpError(
          ErrorCode.InvalidParams,
          `${uri} cannot be subscribed to; these can: ${[...SUBSCRIBABLE].join(', ')}`,
        );
      }
      subscribed.add(uri);
      if (uri !== STATE_URI || stateTimer !== undefined) return;
      let last: Promise<string | undefined> = stateText();
      stateTimer = setInterval(() => {
        last = last.then(async (before) => {
          const now = await stateText();
          if (now !== undefined && now !== before) updated(STATE_URI);
          return now ?? before;
        });
      }, options.statePeriodMs);
      stateTimer.unref?.();
    },
    unsubscribe(uri) {
      subscribed.delete(uri);
      if (uri === STATE_URI && stateTimer !== undefined) {
        clearInterval(stateTimer);
        stateTimer = undefined;
      }
    },
    checkHooked(context) {
      if (!asks(policy) || context.hookConsulted || warnedUnhooked) return;
      warnedUnhooked = true;
      log({
        level: 'error',
        logger: 'mcp',
        message:
          `${context.tool} ran without being asked about: approval is on, but the executor's ` +
          'leash has no approveOverMcp hook (a configuration error of the app)',
      });
    },
  };
}
