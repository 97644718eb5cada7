import { HalError, failureResult } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';
import { callWithTimeout } from './call-with-timeout.js';
import { parseFleetCommand, runFleetCommand } from './commands.js';
import type { FleetCommand } from './commands.js';
import type { FleetMember } from './members.js';
import { fleetReport } from './report.js';
import type { FleetMode, FleetReport, MemberResult } from './report.js';
import type { FleetScheduler } from './scheduler.js';

/** A call made on each member: receives the member's HAL and device id. */
export type MemberCall = (hal: HardwareAbstractionLayer, device: string) => Promise<HALToolResult>;

/** Options of one synchronized call. */
export interface SynchronizedOptions {
  /** Give up waiting for a member after this many ms; its result is then TIMEOUT. */
  timeoutMs?: number;
  /** Only these members (default all). An unknown id is refused before anything runs. */
  devices?: readonly string[];
}

/** Default per-member wait of a synchronized call, ms (a long moveTo may need more). */
export const DEFAULT_CALL_TIMEOUT_MS = 60_000;

/** Turns a command (data or a function) into a call; bad data throws INVALID_PARAMETER. */
export function memberCallOf(command: FleetCommand | MemberCall): MemberCall {
  if (typeof command === 'function') return command;
  const checked = parseFleetCommand(command);
  return (hal) => runFleetCommand(hal, checked);
}

/**
 * Issues `call` to every member in the same tick (none waits for another's completion), then
 * waits for all of them, each with its own timeout, and reports every member's own result: one
 * member's failure or silence never hides another's outcome. Never rejects.
 */
export async function runOnAll(
  mode: FleetMode,
  members: readonly FleetMember[],
  call: MemberCall,
  timeoutMs: number,
  scheduler: FleetScheduler,
): Promise<FleetReport> {
  const startedAt = scheduler.now();
  const pending = members.map((m) => {
    const issuedAt = scheduler.now();
    const result = callWithTimeout(() => call(m.hal, m.id), {
      mode: m.hal.mode,
      device: m.id,
      timeoutMs,
      scheduler,
    });
    return result.then((r): MemberResult => ({ device: m.id, result: r, issuedAt }));
  });
  const results = await Promise.all(pending);
  return fleetReport(mode, results, startedAt, scheduler.now());
}

/** Every member refused with the same error, nothing issued. */
export function refuseAll(
  mode: FleetMode,
  members: readonly FleetMember[],
  error: HalError,
  scheduler: FleetScheduler,
): FleetReport {
  const now = scheduler.now();
  const results = members.map((m): MemberResult => ({
    device: m.id,
    result: failureResult(m.hal.mode, Date.now(), error, 0),
    issuedAt: now,
  }));
  return fleetReport(mode, results, now, now);
}

/** Checks a timeout option: a positive finite number of ms. */
export function checkTimeout(timeoutMs: number | undefined, fallback: number): number {
  if (timeoutMs === undefined) return fallback;
  if (typeof timeoutMs !== 'number' || !Number.isFinite(timeoutMs) || timeoutMs <= 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `timeoutMs must be a positive number of ms, got ${String(timeoutMs)}`,
      { details: { parameter: 'timeoutMs', received: timeoutMs } },
    );
  }
  return timeoutMs;
}
