import type { ToolProfile } from '@hal/skills';
import type { AgentTool, ToolCall, ToolResult } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { TaskVariant } from './variant.js';

/** What an agent gets for one trial. */
export interface AgentTrial {
  /** What the robot should do, in words (the task's instruction). */
  instruction: string;
  /** The tools it may call, under the task's leash and budget. */
  tools: AgentTool[];
  execute(call: ToolCall): Promise<ToolResult>;
  /** Fires when the trial's time is up; the agent should answer at once. */
  signal: AbortSignal;
  /** The most tool calls the task allows. */
  maxToolCalls: number;
  /**
   * The task and its world as the seed placed them: ground truth, given only to agents that
   * declare `usesGroundTruth` (the oracle), never to an agent under test.
   */
  truth?: TaskVariant;
  /** With `truth`: the robot's true pose now (metres, radians), read without a tool call. */
  truePose?: () => { x: number; y: number; yaw: number };
  /**
   * The robot as a HAL for agents that drive one (the navigation bridge): never the robot's own
   * HAL, but one whose motion and sensor calls and e-stop reset go through `execute`, so they are
   * counted, leashed, faulted and logged as tool calls are.
   */
  hal: HardwareAbstractionLayer;
}

/**
 * Why an agent's model could not be used in a trial: it never answered (an endpoint that could
 * not be reached or refused every request, a local model that could not load or whose grammar
 * could not be built). Such a trial is no score of the task: it is counted apart.
 */
export interface ModelFailure {
  /** The failure's code: the endpoint's (NETWORK, HTTP, TIMEOUT...) or the model's own. */
  code: string;
  /** What went wrong, with its cause (host, errno, status). */
  message: string;
}

/** What an agent says at the end of a trial. */
export interface AgentAnswer {
  /** Its final words (a perception task's answer is read from them). */
  answer: string;
  tokensIn?: number;
  tokensOut?: number;
  /** Time spent in the model, ms (not part of the deterministic report). */
  modelMs?: number;
  /** Why it stopped early, if it did (an endpoint error, its step cap). */
  stopped?: string;
  /** Set when the agent's model never answered in the trial: the trial is then not scored. */
  modelFailure?: ModelFailure;
}

/** An agent the harness can score. */
export interface EvalAgent {
  /** A short name for reports, e.g. `oracle`, `local:SmolLM2`. */
  readonly name: string;
  /**
   * Gets the ground truth (`truth`, `truePose`): an oracle, which the report marks as one, not an
   * agent under test. Default false.
   */
  readonly usesGroundTruth?: boolean;
  /**
   * The tools it is offered unless the run names a profile (`hal eval --tools`): `primitives`
   * (the HAL's calls, the default), `skills` or `all` (see @hal/skills).
   */
  readonly toolProfile?: ToolProfile;
  run(trial: AgentTrial): Promise<AgentAnswer>;
}
