// Progress of a motion call for a client that asked for it (a progressToken): the distance
// travelled along the path, or the angle turned, read from the pose at a steady rate, each
// report larger than the last (as MCP requires), the last at the total when the call succeeded.
import type { HardwareAbstractionLayer, Pose } from '@hal/types';
import { angleDifference } from '@hal/types';
import type { MotionSummary, ProgressUnit } from './motion-words.js';

/** How often the pose is read while a motion runs, ms (a robot reports its pose at about 10 Hz). */
export const DEFAULT_PROGRESS_PERIOD_MS = 200;

/** Sends one progress report. */
export type SendProgress = (report: {
  progress: number;
  total?: number;
  message: string;
}) => Promise<void>;

/** A watch over one call; `finish` sends the last report and stops. */
export interface ProgressWatch {
  finish(succeeded: boolean): Promise<void>;
}

/** Smallest step worth a report: 5 mm, or one degree. */
const STEP: Record<ProgressUnit, number> = { m: 0.005, deg: 1 };
const DIGITS: Record<ProgressUnit, number> = { m: 3, deg: 1 };

const round = (v: number, unit: ProgressUnit) => Number(v.toFixed(DIGITS[unit]));

function text(done: number, total: number | undefined, unit: ProgressUnit): string {
  const what = unit === 'm' ? 'm travelled' : 'degrees turned';
  return total === undefined ? `${done} ${what}` : `${done} of ${total} ${what}`;
}

/**
 * Watches `hal`'s pose while the motion `summary` describes runs, reporting through `send` every
 * `periodMs` when it has gone a step further. Never throws: a report that fails is dropped.
 */
export function watchProgress(
  hal: HardwareAbstractionLayer,
  summary: MotionSummary,
  send: SendProgress,
  periodMs = DEFAULT_PROGRESS_PERIOD_MS,
): ProgressWatch {
  const { unit } = summary.progress;
  const total =
    summary.progress.total === undefined ? undefined : round(summary.progress.total, unit);
  let last: Pose | undefined;
  let done = 0;
  let sent = 0;
  let reading: Promise<void> = Promise.resolve();

  const report = async (value: number) => {
    if (value <= sent) return;
    sent = value;
    await send({
      progress: value,
      ...(total === undefined ? {} : { total }),
      message: text(value, total, unit),
    }).catch(() => undefined);
  };

  const read = async () => {
    let pose: Pose;
    try {
      pose = await hal.locomotion.getPose();
    } catch {
      return;
    }
    if (last !== undefined) {
      done +=
        unit === 'm'
          ? Math.hypot(pose.position.x - last.position.x, pose.position.y - last.position.y)
          : (Math.abs(angleDifference(pose.rotation.yaw, last.rotation.yaw)) * 180) / Math.PI;
    }
    last = pose;
  };

  const now = () => round(total === undefined ? done : Math.min(done, total), unit);

  reading = read();
  const timer = setInterval(() => {
    // one read at a time: a slow pose is not read twice over
    reading = reading.then(async () => {
      await read();
      const value = now();
      if (value >= sent + STEP[unit]) await report(value);
    });
  }, periodMs);
  timer.unref?.();

  return {
    async finish(succeeded) {
      clearInterval(timer);
      await reading;
      await read();
      await report(succeeded && total !== undefined ? total : now());
    },
  };
}
