import { HalError } from '@hal/types';
import type { HALToolResult } from '@hal/types';
import type { PlanarPose } from '@hal/types';
import type { FormationOffset } from './formation.js';

/** How a leader-follower formation is run. Distances in metres, times in ms on the fleet clock. */
export interface LeaderFollowerOptions {
  /** The leader's device id. The formation never commands the leader; you drive it. */
  leader: string;
  /** Each follower's slot in the leader's frame (x ahead, y left), by device id. */
  formation: Readonly<Record<string, FormationOffset>>;
  /** Control loop period, ms. Default 100 (10 Hz). */
  periodMs?: number;
  /** A follower closer than this to its slot holds still. Default 0.03 m. */
  toleranceM?: number;
  /** Turn a follower in its slot to the leader's heading. Default true. */
  alignHeading?: boolean;
  /** Heading error a follower in its slot accepts, degrees. Default 10. */
  headingToleranceDeg?: number;
  /** Interrupt a follower's move when its slot has moved this far from the move's target. Default 0.1 m. */
  retargetM?: number;
  /** Followers' cruise speed, m/s, clamped to each follower's limits. Default each one's top speed. */
  speedMPerS?: number;
  /** End the formation once the leader has moved, then stood still, and every follower is in its slot. Default true. */
  stopWhenLeaderStops?: boolean;
  /** The leader counts as stopped after this long without moving (1 mm, 0.5 degrees). Default 1000 ms. */
  leaderStillMs?: number;
  /** After the leader stops, give followers this long to reach their slots. Default 120000 ms. */
  settleTimeoutMs?: number;
  /** Wait for a pose at most this long. Default 2000 ms. */
  readTimeoutMs?: number;
  /** Wait for a follower's move at most this long. Default 60000 ms. */
  callTimeoutMs?: number;
  /** End the formation after this many ticks in a row without the leader's pose. Default 20. */
  maxLeaderFailures?: number;
}

/** Why a formation ended. */
export type FormationEndReason =
  'leader-stopped' | 'stopped' | 'estop' | 'leader-lost' | 'settle-timeout';

/** A follower's state at the end of a formation. */
export interface FollowerReport {
  device: string;
  offset: FormationOffset;
  /** The slot for the leader's last known pose. */
  slot?: { x: number; y: number };
  /** The follower's last pose (absent when it could not be read). */
  pose?: PlanarPose;
  /** Distance from pose to slot, metres. */
  errorM?: number;
  /** The result of the follower's last move. */
  lastResult?: HALToolResult;
}

/** What a formation reports when it ends. */
export interface FormationReport {
  reason: FormationEndReason;
  /** The member whose e-stop ended the formation (reason 'estop'). */
  estopDevice?: string;
  leader: string;
  leaderPose?: PlanarPose;
  followers: FollowerReport[];
  /** Control loop ticks run. */
  ticks: number;
}

export type ResolvedOptions = Required<Omit<LeaderFollowerOptions, 'speedMPerS'>> & {
  speedMPerS: number | undefined;
};

function positive(name: string, value: number | undefined, fallback: number): number {
  if (value === undefined) return fallback;
  if (typeof value !== 'number' || !Number.isFinite(value) || value <= 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `${name} must be a positive number, got ${String(value)}`,
      {
        details: { parameter: name, received: value },
      },
    );
  }
  return value;
}

/** Fills defaults and checks every option; a bad one is INVALID_PARAMETER naming it. */
export function resolveOptions(o: LeaderFollowerOptions): ResolvedOptions {
  for (const [device, offset] of Object.entries(o.formation ?? {})) {
    if (
      typeof offset !== 'object' ||
      offset === null ||
      !Number.isFinite(offset.x) ||
      !Number.isFinite(offset.y)
    ) {
      throw new HalError(
        'INVALID_PARAMETER',
        `formation offset of "${device}" must be {x, y} in finite metres`,
        { details: { parameter: 'formation', device, received: offset } },
      );
    }
  }
  return {
    leader: o.leader,
    formation: o.formation,
    periodMs: positive('periodMs', o.periodMs, 100),
    toleranceM: positive('toleranceM', o.toleranceM, 0.03),
    alignHeading: o.alignHeading ?? true,
    headingToleranceDeg: positive('headingToleranceDeg', o.headingToleranceDeg, 10),
    retargetM: positive('retargetM', o.retargetM, 0.1),
    speedMPerS: o.speedMPerS === undefined ? undefined : positive('speedMPerS', o.speedMPerS, 0),
    stopWhenLeaderStops: o.stopWhenLeaderStops ?? true,
    leaderStillMs: positive('leaderStillMs', o.leaderStillMs, 1000),
    settleTimeoutMs: positive('settleTimeoutMs', o.settleTimeoutMs, 120_000),
    readTimeoutMs: positive('readTimeoutMs', o.readTimeoutMs, 2000),
    callTimeoutMs: positive('callTimeoutMs', o.callTimeoutMs, 60_000),
    maxLeaderFailures: positive('maxLeaderFailures', o.maxLeaderFailures, 20),
  };
}
