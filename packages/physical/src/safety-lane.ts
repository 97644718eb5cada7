import { HalError } from '@hal/types';
import type { Command, ReplyOf } from './protocol/schemas.js';
import type { RequestOptions } from './transport/transport.js';

/*
 * The safety lane of protocol 1.1, section 4.1: `stop` and `estop` are sent at once, beside any
 * pending request, and resent until acknowledged. This file holds its timing and the signal that
 * tells pending motion calls a stop was issued, and acknowledged.
 */

/** How the safety lane resends a `stop` or `estop` until the robot acknowledges it. */
export interface SafetyLaneTiming {
  /** Resend after this long without a reply, ms. */
  resendMs: number;
  /** Give up after this long in all, ms. */
  totalMs: number;
}

/**
 * Resend every 20 ms for up to the protocol's 3 x 2000 ms: at 30% loss a stop then reaches the
 * robot within 4 sends (60 ms) 99 times in 100. Duplicates are harmless: a stop is idempotent.
 */
export const DEFAULT_SAFETY_LANE: SafetyLaneTiming = { resendMs: 20, totalMs: 6000 };

/** A stop or e-stop the robot acknowledged, with its reply. */
export type SafetyInterrupt =
  { cmd: 'stop'; reply: ReplyOf<'stop'> } | { cmd: 'estop'; reply: ReplyOf<'estop'> };

/** The commands of the safety lane (protocol 1.1, section 4.1). */
export type SafetyCommand = 'stop' | 'estop';

/** Commands that move the wheels: never sent once a stop issued after them went out. */
const MOTION_COMMANDS: ReadonlySet<Command> = new Set([
  'move_steps',
  'move_cm',
  'rotate_deg',
  'drive',
]);

/** Whether a command moves the wheels. */
export function isMotionCommand(cmd: Command): boolean {
  return MOTION_COMMANDS.has(cmd);
}

/**
 * The lane timing a command's request options ask for: their attempts x timeout as its total
 * wait, at the lane's usual resend period; undefined (the session's own) when they set neither.
 */
export function laneBound(options: RequestOptions): SafetyLaneTiming | undefined {
  if (options.attempts === undefined && options.timeoutMs === undefined) return undefined;
  return {
    resendMs: DEFAULT_SAFETY_LANE.resendMs,
    totalMs: (options.attempts ?? 1) * (options.timeoutMs ?? DEFAULT_SAFETY_LANE.totalMs),
  };
}

/** The resend period and the number of sends for a lane timing. */
export function laneAttempts(timing: SafetyLaneTiming): { timeoutMs: number; attempts: number } {
  const timeoutMs = Math.max(1, timing.resendMs);
  return { timeoutMs, attempts: Math.max(1, Math.ceil(timing.totalMs / timeoutMs)) };
}

/**
 * Counts the stops issued (the epoch), so a motion command queued before one is never sent, and
 * wakes the motion calls waiting for one to be acknowledged.
 */
export class StopSignal {
  #epoch = 0;
  #last: SafetyCommand = 'stop';
  readonly #waiters = new Set<{ after: number; wake: (i: SafetyInterrupt) => void }>();

  /** The number of stops issued so far. */
  get epoch(): number {
    return this.#epoch;
  }

  /** A stop is being issued; returns its epoch. */
  issue(cmd: SafetyCommand): number {
    this.#epoch += 1;
    this.#last = cmd;
    return this.#epoch;
  }

  /** The robot acknowledged the stop of `epoch`: wakes every waiter from before it. */
  acknowledged(epoch: number, interrupt: SafetyInterrupt): void {
    for (const waiter of [...this.#waiters]) {
      if (waiter.after < epoch) waiter.wake(interrupt);
    }
  }

  /**
   * Resolves when the robot acknowledges a stop issued after `epoch` was read. Never rejects; a
   * stop that is never acknowledged never resolves it.
   */
  interrupted(epoch: number): Promise<SafetyInterrupt> {
    return new Promise((resolve) => {
      const waiter = {
        after: epoch,
        wake: (interrupt: SafetyInterrupt) => {
          this.#waiters.delete(waiter);
          resolve(interrupt);
        },
      };
      this.#waiters.add(waiter);
    });
  }

  /** The error of a motion command dropped from the queue because a stop overtook it. */
  overtaken(cmd: Command): HalError {
    const estop = this.#last === 'estop';
    return new HalError(
      estop ? 'EMERGENCY_STOPPED' : 'INTERRUPTED',
      `"${cmd}" was not sent: ${estop ? 'an emergency stop' : 'a stop'} was issued after it`,
      { details: { command: cmd } },
    );
  }
}
