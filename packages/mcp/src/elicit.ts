// Asks the client's user, by MCP elicitation, to approve a motion; answers the decision, the
// reason saying which it was: declined, cancelled, unanswered in time, or no one to ask.
import type { Server } from '@modelcontextprotocol/sdk/server/index.js';
import { ErrorCode, McpError } from '@modelcontextprotocol/sdk/types.js';
import type { RequestId } from '@modelcontextprotocol/sdk/types.js';
import type { ApprovalDecision } from '@hal/tools';
import { errorMessage } from '@hal/types';

/** Why nothing moves when the client cannot be asked. */
export const NO_ELICITATION =
  'no one can approve it: the MCP client did not declare the elicitation capability, ' +
  'and this server asks before motions (use a client that supports elicitation, or run the ' +
  'server without approval)';

const withdrawn = (words: string): ApprovalDecision => ({
  allow: false,
  reason: `a stop came while the question was open (${words}); nothing moved`,
});

/** The request the question belongs to. */
export interface AskingRequest {
  requestId: RequestId;
  signal: AbortSignal;
}

/** Whether the connected client said it can answer form elicitations. */
export function canElicit(server: Server): boolean {
  return server.getClientCapabilities()?.elicitation?.form !== undefined;
}

/**
 * A question for `server`'s client within `request`: "Allow the robot to <words>?", with only
 * accept, decline and cancel as answers, unanswered after `timeoutMs`. `stopped()` answers the
 * signal of the next stop: a stop or an e-stop while the question is open withdraws it (no).
 */
export function elicitApproval(
  server: Server,
  request: AskingRequest,
  timeoutMs: number,
  stopped: () => AbortSignal,
): (words: string) => Promise<ApprovalDecision> {
  return async (words) => {
    if (!canElicit(server)) return { allow: false, reason: `${NO_ELICITATION}; nothing moved` };
    const stop = stopped();
    try {
      const answer = await server.elicitInput(
        {
          mode: 'form',
          message: `Allow the robot to ${words}?`,
          requestedSchema: { type: 'object', properties: {} },
        },
        {
          relatedRequestId: request.requestId,
          timeout: timeoutMs,
          signal: AbortSignal.any([request.signal, stop]),
        },
      );
      if (stop.aborted) return withdrawn(words);
      if (answer.action === 'accept') return { allow: true };
      return {
        allow: false,
        reason:
          answer.action === 'decline'
            ? `the user declined (${words}); nothing moved`
            : `the user cancelled the question (${words}); nothing moved`,
      };
    } catch (thrown) {
      if (stop.aborted) return withdrawn(words);
      if (thrown instanceof McpError && thrown.code === ErrorCode.RequestTimeout) {
        return {
          allow: false,
          reason: `no answer within ${timeoutMs / 1000} s (${words}); nothing moved`,
        };
      }
      if (request.signal.aborted) {
        return { allow: false, reason: 'the tool call was cancelled; nothing moved' };
      }
      const why = errorMessage(thrown);
      return { allow: false, reason: `the question failed: ${why}; nothing moved` };
    }
  };
}
