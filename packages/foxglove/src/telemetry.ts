// A physical robot's own reports (PhysicalHAL's reportedSteps(), transportStats(), linkState),
// read by shape as the recorder reads them, in the recorder's WheelSteps and LinkStats forms. A
// HAL without them (the simulator) has neither topic.
import type { LinkStats, WheelSteps } from '@hal/recorder';

type Reader<R> = (() => R | undefined) | undefined;

function method<R>(hal: object, name: string): Reader<R> {
  const fn: unknown = Reflect.get(hal, name, hal);
  return typeof fn === 'function' ? () => (fn as () => R | undefined).call(hal) : undefined;
}

interface StepsLike {
  leftSteps: number;
  rightSteps: number;
  leftStepsPerS: number;
  rightStepsPerS: number;
  robotUptimeMs: number;
}

interface TransportLike {
  sent: number;
  received: number;
  timeouts: number;
  retries: number;
  dropped: number;
  rttP50Ms: number;
  rttP99Ms: number;
}

/** The readers `hal` offers (each absent when it has none). */
export function telemetryOf(hal: object): {
  steps?: () => WheelSteps | undefined;
  link?: () => LinkStats | undefined;
} {
  const steps = method<StepsLike>(hal, 'reportedSteps');
  const transport = method<TransportLike>(hal, 'transportStats');
  return {
    ...(steps === undefined
      ? {}
      : {
          steps: () => {
            const s = steps();
            return s === undefined
              ? undefined
              : {
                  left_steps: s.leftSteps,
                  right_steps: s.rightSteps,
                  left_steps_per_s: s.leftStepsPerS,
                  right_steps_per_s: s.rightStepsPerS,
                  robot_uptime_ms: s.robotUptimeMs,
                };
          },
        }),
    ...(transport === undefined
      ? {}
      : {
          link: () => {
            const t = transport();
            if (t === undefined) return undefined;
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
            };
          },
        }),
  };
}
