import { HAL_CALL_TABLE, HalBoundary, withTimeout, errorMessage } from '@hal/types';
import type {
  CallName,
  CallTable,
  HALToolResult,
  HardwareAbstractionLayer,
  RobotConfig,
} from '@hal/types';
import { parseArguments } from './arguments.js';
import { dispatch } from './dispatch.js';
import { checkMotion, RateLimiter } from './leash.js';
import type { ApprovalDecision, Leash } from './leash.js';
import { planMotion } from './motion-plan.js';
import type { PlanStart } from './motion-plan.js';
import { errorResult, fromHalResult, fromThrown, fromValue } from './result.js';
import type { ToolResult } from './result.js';
import { robotConfigOf } from './robot-config.js';
import { callTimeoutMs, DEFAULT_TOOL_TIMEOUT_MS } from './timeouts.js';
import { halTools } from './tools.js';
import type { HalTool } from './tools.js';

/** A tool call as an LLM sends it. */
export interface ToolCall {
  name: string;
  /** JSON text (chat-completions), an object (Anthropic, MCP), or nothing. */
  arguments: string | Record<string, unknown> | undefined;
  id?: string;
}

/** How {@link createToolExecutor} runs calls. */
export interface ToolExecutorOptions {
  /** Time a call may take, ms (motions get more: see docs/tools.md). Default 10000. */
  timeoutMs?: number;
  /** Limits on what the LLM may do. */
  leash?: Leash;
  /** The tools offered; default `halTools(hal)`. */
  tools?: HalTool[];
  /** The clock of the rate limit, ms. Default `Date.now`. */
  now?: () => number;
  /** The calls the tools run; default the HAL's own call table (pass the one `tools` came from). */
  calls?: CallTable;
}

/** Runs tool calls on a HAL. */
export interface ToolExecutor {
  tools: HalTool[];
  /** Runs one call; never throws: every refusal and failure is a result the LLM can read. */
  execute(call: ToolCall): Promise<ToolResult>;
}

function isResult(value: unknown): value is HALToolResult {
  return (
    typeof value === 'object' &&
    value !== null &&
    typeof (value as { success?: unknown }).success === 'boolean' &&
    'mode' in value
  );
}

/** Validates arguments the way the HAL will, so the leash sees what will run. */
function validate(
  config: RobotConfig,
  hal: HardwareAbstractionLayer,
  call: CallName,
  args: unknown,
  table: CallTable,
) {
  if (table !== HAL_CALL_TABLE) {
    const spec = table.find((entry) => entry.name === call);
    const own = HAL_CALL_TABLE.find((entry) => entry.name === call);
    if (spec !== undefined && own === undefined) {
      // a call of an extended table: the HAL's boundary does not know it; its schema does
      const parsed = spec.paramsSchema(config).safeParse(args);
      if (parsed.success)
        return { ok: true as const, args: parsed.data as Record<string, unknown> };
      const issue = parsed.error.issues[0];
      return {
        ok: false as const,
        result: errorResult(
          'INVALID_PARAMETER',
          `${call}: "${issue?.path.join('.') ?? 'arguments'}" is invalid: ${issue?.message ?? 'invalid'}`,
        ),
      };
    }
  }
  const boundary = new HalBoundary({
    mode: hal.mode,
    config: () => config,
    isEmergencyStopped: () => false,
    isReady: () => true,
  });
  try {
    return { ok: true as const, args: boundary.validate(call, args) as Record<string, unknown> };
  } catch (thrown) {
    return { ok: false as const, result: fromThrown(thrown) };
  }
}

async function startOf(hal: HardwareAbstractionLayer): Promise<PlanStart> {
  const pose = await hal.locomotion.getPose();
  return { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
}

/**
 * An executor of tool calls on `hal`: parse, find the tool, validate against the robot's limits,
 * rate limit, approval, the caps and the geofence, then the call under a timeout. `stop` and
 * `emergency_stop` skip every step but the call itself: an e-stop runs whatever its arguments.
 */
export function createToolExecutor(
  hal: HardwareAbstractionLayer,
  options: ToolExecutorOptions = {},
): ToolExecutor {
  const tools = options.tools ?? halTools(hal);
  const byName = new Map(tools.map((t) => [t.name, t]));
  const leash = options.leash ?? {};
  const limiter = leash.rateLimit === undefined ? undefined : new RateLimiter(leash.rateLimit);
  const now = options.now ?? Date.now;
  const table = options.calls ?? HAL_CALL_TABLE;
  const baseTimeout = options.timeoutMs ?? DEFAULT_TOOL_TIMEOUT_MS;

  async function run(tool: HalTool, args: Record<string, unknown>, timeoutMs: number) {
    const work = dispatch(hal, tool.call, args, table);
    let outcome: { value: unknown } | undefined;
    try {
      outcome = await withTimeout(work, timeoutMs);
    } catch (thrown) {
      return fromThrown(thrown);
    }
    if (outcome === undefined) {
      // A motion the executor gave up on must not keep going unattended.
      if (tool.motion) await hal.locomotion.stop().catch(() => undefined);
      work.catch(() => undefined);
      return errorResult(
        'TIMEOUT',
        `${tool.name}: no answer within ${timeoutMs} ms${tool.motion ? '; the wheels were stopped' : ''}`,
      );
    }
    return isResult(outcome.value) ? fromHalResult(outcome.value) : fromValue(outcome.value);
  }

  async function emergencyStop(raw: ToolCall['arguments']): Promise<ToolResult> {
    const parsed = parseArguments(raw);
    const reason = parsed.ok ? parsed.args['reason'] : undefined;
    const text =
      reason === undefined
        ? undefined
        : typeof reason === 'string'
          ? reason
          : JSON.stringify(reason);
    const first = await run(byName.get('emergency_stop') as HalTool, { reason: text }, baseTimeout);
    // Never refused for its argument: should a HAL refuse the reason, stop without one.
    if (first.code === 'INVALID_PARAMETER' || first.code === 'RANGE_EXCEEDED') {
      return run(byName.get('emergency_stop') as HalTool, {}, baseTimeout);
    }
    return first;
  }

  async function execute(call: ToolCall): Promise<ToolResult> {
    const tool = byName.get(call.name);
    if (tool === undefined) {
      return errorResult(
        'UNKNOWN_TOOL',
        `no tool named ${JSON.stringify(call.name)}; the tools are ${[...byName.keys()].join(', ')}`,
      );
    }
    if (tool.safety === 'estop') return emergencyStop(call.arguments);
    if (tool.safety === 'stop') return run(tool, {}, baseTimeout);
    const parsed = parseArguments(call.arguments);
    if (!parsed.ok) return errorResult('BAD_ARGUMENTS', `${tool.name}: ${parsed.message}`);
    const config = robotConfigOf(hal);
    let checked = validate(config, hal, tool.call as CallName, parsed.args, table);
    if (!checked.ok) return checked.result;
    if (limiter !== undefined) {
      const waitMs = limiter.take(now());
      if (waitMs > 0) {
        return errorResult(
          'LEASH_RATE_LIMIT',
          `${tool.name}: too many calls; try again in ${Math.ceil(waitMs)} ms (stop and emergency_stop are always allowed)`,
        );
      }
    }
    if (leash.approve !== undefined) {
      let decision: ApprovalDecision;
      try {
        decision = await leash.approve({ tool, args: checked.args });
      } catch (thrown) {
        // fail closed: a hook that breaks has not approved anything
        const why = errorMessage(thrown);
        return errorResult('DENIED', `${tool.name}: the approval hook failed: ${why}`);
      }
      if (!decision.allow) return errorResult('DENIED', `${tool.name}: denied: ${decision.reason}`);
      if (decision.args !== undefined) {
        checked = validate(config, hal, tool.call as CallName, decision.args, table);
        if (!checked.ok) return checked.result;
      }
    }
    let profileMs: number | undefined;
    if (tool.motion) {
      let start: PlanStart;
      try {
        start = await startOf(hal);
      } catch (thrown) {
        return fromThrown(thrown);
      }
      const plan = planMotion(tool.call, checked.args, start, config, table);
      if (plan !== undefined) {
        const refusal = checkMotion(tool, plan, start, leash, table);
        if (refusal !== undefined) return refusal;
        profileMs = plan.durationMs;
      }
    }
    return run(tool, checked.args, callTimeoutMs(baseTimeout, profileMs));
  }

  return {
    tools,
    async execute(call) {
      try {
        return await execute(call);
      } catch (thrown) {
        return fromThrown(thrown);
      }
    },
  };
}
