// The MCP tool call under way, as the code it runs sees it: the leash's approval hook runs deep in
// the executor (and in a skill's own motions), far from the request, and asks the request's client
// through this context. An AsyncLocalStorage follows the call through every await.
import { AsyncLocalStorage } from 'node:async_hooks';
import type { ApprovalDecision } from '@hal/tools';
import type { ApprovalPolicy } from './approval-policy.js';
import type { Summarize } from './motion-words.js';

/** One tool call a client made. */
export interface CallContext {
  /** The tool called. */
  readonly tool: string;
  /** When the server asks before a motion. */
  readonly policy: ApprovalPolicy;
  /** Asks the client's user to approve what `words` says; answers their decision. */
  ask(words: string): Promise<ApprovalDecision>;
  /** What a motion call will do, from the pose now. */
  summarize: Summarize;
  /** Set once the user approved the whole call (a skill): its own motions are not asked again. */
  approved: boolean;
  /** Set when the leash's approval hook was consulted during the call. */
  hookConsulted: boolean;
}

const store = new AsyncLocalStorage<CallContext>();

/** Runs `work` as the tool call `context`. */
export function inCall<T>(context: CallContext, work: () => Promise<T>): Promise<T> {
  return store.run(context, work);
}

/** The tool call under way, or undefined outside one. */
export function currentCall(): CallContext | undefined {
  return store.getStore();
}
