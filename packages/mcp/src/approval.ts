// Approval of motions by the MCP client's user: the leash's approval hook (`approveOverMcp`, put
// in the executor's leash) and the server's own gate for a skill, one decision for both.
import type { AgentTool, ApprovalDecision, HalTool } from '@hal/tools';
import { needsApproval } from './approval-policy.js';
import { currentCall } from './call-context.js';
import type { CallContext } from './call-context.js';
import type { Summarize } from './motion-words.js';

const ALLOW: ApprovalDecision = { allow: true };

/**
 * Decides one call of `tool` inside the MCP call `context`: stops and the e-stop are never held
 * (the executor does not even show them to the hook), a call that does not move passes, as does a
 * motion inside a call the user already approved, or one the policy lets through; any other is
 * asked about. The user's answer is the decision.
 */
export async function decide(
  context: CallContext,
  tool: AgentTool,
  args: Record<string, unknown>,
  summarize: Summarize,
): Promise<ApprovalDecision> {
  if (tool.safety !== undefined || !tool.motion) return ALLOW;
  if (context.approved || context.policy === 'none') return ALLOW;
  const summary = await summarize(tool, args);
  if (summary === undefined || !needsApproval(context.policy, summary.distanceM)) return ALLOW;
  const decision = await context.ask(`${tool.name}: ${summary.words}`);
  if (decision.allow) context.approved = true;
  return decision;
}

/**
 * The leash's approval hook for a server with `approve` set: put it in the executor's leash
 * (`createToolExecutor(hal, { leash: { approve: approveOverMcp } })`) and every HAL motion an MCP
 * client's call makes, directly or inside a skill, is asked about as the server's policy says.
 * Outside an MCP tool call it refuses: nobody is there to approve.
 */
export async function approveOverMcp(call: {
  tool: HalTool;
  args: Record<string, unknown>;
}): Promise<ApprovalDecision> {
  const context = currentCall();
  if (context === undefined) {
    return {
      allow: false,
      reason: 'no MCP tool call is under way, so no one can be asked to approve it',
    };
  }
  context.hookConsulted = true;
  return decide(context, call.tool, call.args, context.summarize);
}
