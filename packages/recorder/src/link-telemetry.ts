import type { SerialLinkStats, TransportStats } from '@hal/types';
import type { LinkStats, WheelSteps } from './messages.js';

/*
 * What a physical HAL reports beyond the HAL interface (PhysicalHAL's `reportedSteps()`,
 * `transportStats()`, `linkStats()` and `linkState`), read by shape: the recorder depends on no
 * concrete HAL, and a HAL without them (the simulator) records neither topic.
 */

interface ReportedStepsLike {
  leftSteps: number;
  rightSteps: number;
  leftStepsPerS: number;
  rightStepsPerS: number;
  robotUptimeMs: number;
}

/** The readers a HAL offers, each bound to it; absent when it has none. */
export interface LinkTelemetry {
  steps?: () => WheelSteps | undefined;
  link?: () => LinkStats | undefined;
}

function method<R>(hal: object, name: string): (() => R) | undefined {
  const fn: unknown = Reflect.get(hal, name, hal);
  return typeof fn === 'function' ? () => (fn as () => R).call(hal) : undefined;
}

function serialOf(s: SerialLinkStats): NonNullable<LinkStats['serial']> {
  return {
    frames_sent: s.framesSent,
    frames_received: s.framesReceived,
    acks_sent: s.acksSent,
    acks_received: s.acksReceived,
    frame_retries: s.frameRetries,
    frame_timeouts: s.frameTimeouts,
    checksum_errors: s.checksumErrors,
    resync_bytes: s.resyncBytes,
    duplicate_frames: s.duplicateFrames,
  };
}

/** The step and link readers of `hal`, for those of PhysicalHAL's accessors it has. */
export function linkTelemetry(hal: object): LinkTelemetry {
  const reportedSteps = method<ReportedStepsLike | undefined>(hal, 'reportedSteps');
  const transportStats = method<TransportStats | undefined>(hal, 'transportStats');
  const serialStats = method<SerialLinkStats | undefined>(hal, 'linkStats');
  const out: LinkTelemetry = {};
  if (reportedSteps !== undefined) {
    out.steps = () => {
      const s = reportedSteps();
      return s === undefined
        ? undefined
        : {
            left_steps: s.leftSteps,
            right_steps: s.rightSteps,
            left_steps_per_s: s.leftStepsPerS,
            right_steps_per_s: s.rightStepsPerS,
            robot_uptime_ms: s.robotUptimeMs,
          };
    };
  }
  if (transportStats !== undefined) {
    out.link = () => {
      const t = transportStats();
      if (t === undefined) return undefined;
      const serial = serialStats?.();
      const state: unknown = Reflect.get(hal, 'linkState', hal);
      return {
        link_state: typeof state === 'string' ? state : 'unknown',
        sent: t.sent,
        received: t.received,
        retries: t.retries,
        timeouts: t.timeouts,
        unanswered: Math.max(0, t.sent - t.received),
        dropped: t.dropped,
        rtt_p50_ms: t.rttP50Ms,
        rtt_p99_ms: t.rttP99Ms,
        ...(serial === undefined ? {} : { serial: serialOf(serial) }),
      };
    };
  }
  return out;
}

/** Whether two step reports are the same report (the robot said nothing new). */
export function sameSteps(a: WheelSteps | undefined, b: WheelSteps): boolean {
  return (
    a !== undefined &&
    a.left_steps === b.left_steps &&
    a.right_steps === b.right_steps &&
    a.left_steps_per_s === b.left_steps_per_s &&
    a.right_steps_per_s === b.right_steps_per_s &&
    a.robot_uptime_ms === b.robot_uptime_ms
  );
}
