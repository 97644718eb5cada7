import type { RobotConfig } from '@hal/types';
import type { PoseTracker } from '../pose-tracker.js';
import type { Command, ReplyOf, RequestParams } from '../protocol/schemas.js';
import type { SafetyCommand, SafetyInterrupt } from '../safety-lane.js';
import type { LinkTiming } from './link-timing.js';
import type { SafetyCache } from './safety-cache.js';

/** What running a motion over the wire session needs (the wire binding's parts). */
export interface HalContext {
  /** The robot configuration, as the robot last reported it. */
  robot(): RobotConfig;
  /** The host's dead reckoning of the pose. */
  readonly tracker: PoseTracker;
  readonly timing: LinkTiming;
  /** The e-stop latches and the last safety report. */
  readonly safety: SafetyCache;
  /** Sends one command in the current session; rejects with a HalError. */
  command<C extends Command>(cmd: C, params: RequestParams[C]): Promise<ReplyOf<C>>;
  /**
   * Sends `stop` or `estop` on the safety lane (never queued); resolves undefined when there is no
   * session to send it in (before `initialize()`, after `cleanup()`).
   */
  safetyCommand<C extends SafetyCommand>(
    cmd: C,
    params: RequestParams[C],
  ): Promise<ReplyOf<C> | undefined>;
  /** The number of stops issued so far. */
  safetyEpoch(): number;
  /** Resolves when a stop issued after `epoch` is acknowledged (never rejects). */
  interrupted(epoch: number): Promise<SafetyInterrupt>;
}
