import { HAL_CALL_TABLE, findCall } from '@hal/types';
import type { CallTable } from '@hal/types';
import type { MotionPlan, PlanStart } from './motion-plan.js';
import { errorResult } from './result.js';
import type { ToolResult } from './result.js';
import type { HalTool } from './tools.js';

/** What an approval hook answers: allow (maybe with changed arguments) or deny with a reason. */
export type ApprovalDecision =
  { allow: true; args?: Record<string, unknown> } | { allow: false; reason: string };

/** A rectangle of the world frame, metres (REP-103). */
export interface Geofence {
  minX: number;
  maxX: number;
  minY: number;
  maxY: number;
}

/**
 * Limits an app puts on what an LLM may do. Stop and emergency stop are never subject to any of
 * them (they are not even shown to `approve`).
 */
export interface Leash {
  /** Asked before every other call runs: allow, deny, or allow with changed arguments. */
  approve?: (call: {
    tool: HalTool;
    args: Record<string, unknown>;
  }) => Promise<ApprovalDecision> | ApprovalDecision;
  /** Longest path one motion call may take, metres. */
  maxDistanceM?: number;
  /** Fastest a wheel may go in one call, m/s. */
  maxSpeedMPerS?: number;
  /** A motion must not end outside this rectangle (metres, REP-103 world frame). */
  geofence?: Geofence;
  /** At most `calls` tool calls (stops aside) in any `perMs` window. */
  rateLimit?: { calls: number; perMs: number };
}

/** How far a point is outside the fence, metres (0 inside). */
function outside(fence: Geofence, p: { x: number; y: number }): number {
  const dx = Math.max(fence.minX - p.x, 0, p.x - fence.maxX);
  const dy = Math.max(fence.minY - p.y, 0, p.y - fence.maxY);
  return Math.hypot(dx, dy);
}

const round = (v: number) => Math.round(v * 1000) / 1000;

/** A straight drive takes no speed: it always runs at the robot's top speed. */
function runsAtTopSpeed(call: string, table: CallTable): boolean {
  const motion = findCall(call, table)?.motion;
  return motion === 'forward' || motion === 'backward';
}

/**
 * Checks a planned motion against the leash's caps and geofence; answers the refusal, or
 * undefined. A motion may end outside the fence only if it ends nearer to it than it started (so
 * a robot that is outside can be brought back and turned in place).
 */
export function checkMotion(
  tool: HalTool,
  plan: MotionPlan,
  start: PlanStart,
  leash: Leash,
  table: CallTable = HAL_CALL_TABLE,
): ToolResult | undefined {
  if (leash.maxDistanceM !== undefined && plan.distanceM > leash.maxDistanceM) {
    return errorResult(
      'LEASH_DISTANCE',
      plan.distanceM === Infinity
        ? `${tool.name}: a drive without durationMs has no end; the leash allows at most ${leash.maxDistanceM} m per call`
        : `${tool.name}: would travel ${round(plan.distanceM)} m; the leash allows at most ${leash.maxDistanceM} m per call`,
    );
  }
  if (leash.maxSpeedMPerS !== undefined && plan.speedMPerS > leash.maxSpeedMPerS) {
    return errorResult(
      'LEASH_SPEED',
      `${tool.name}: would run at ${round(plan.speedMPerS)} m/s; the leash allows at most ${leash.maxSpeedMPerS} m/s` +
        (runsAtTopSpeed(tool.call, table)
          ? ' (this call runs at top speed: use move_to with a speed)'
          : ''),
    );
  }
  const fence = leash.geofence;
  if (fence !== undefined) {
    if (plan.path === undefined) {
      return errorResult(
        'LEASH_GEOFENCE',
        `${tool.name}: a drive without durationMs has no predictable end; the geofence needs one`,
      );
    }
    const before = outside(fence, start);
    for (const point of plan.path) {
      const after = outside(fence, point);
      if (after > 0 && after >= before + 1e-9) {
        const end = plan.path[plan.path.length - 1] ?? point;
        return errorResult(
          'LEASH_GEOFENCE',
          `${tool.name}: would take the robot to (${round(end.x)}, ${round(end.y)}) m, outside the geofence ` +
            `x ${fence.minX}..${fence.maxX}, y ${fence.minY}..${fence.maxY}`,
        );
      }
    }
  }
  return undefined;
}

/** A sliding-window rate limit on tool calls. */
export class RateLimiter {
  readonly #calls: number;
  readonly #perMs: number;
  readonly #times: number[] = [];

  constructor(limit: { calls: number; perMs: number }) {
    this.#calls = limit.calls;
    this.#perMs = limit.perMs;
  }

  /** Takes a slot now; answers how many ms until one frees up when none is free (taking none). */
  take(now: number): number {
    while (this.#times.length > 0 && now - (this.#times[0] ?? now) >= this.#perMs)
      this.#times.shift();
    if (this.#times.length >= this.#calls) return this.#perMs - (now - (this.#times[0] ?? now));
    this.#times.push(now);
    return 0;
  }
}
