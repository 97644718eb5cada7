/*
 * A recording as the demo plays it back: the robot's poses and its camera frames on one time
 * line (milliseconds from the first of them), and what is shown at a time.
 */

/** A recorded pose, `t` ms after the time line starts. */
export interface TimedPose {
  t: number;
  x: number;
  y: number;
  yaw: number;
}

/** A recorded camera frame (a data URL an <img> shows), `t` ms after the time line starts. */
export interface TimedFrame {
  t: number;
  src: string;
}

export interface PlaybackTimeline {
  /** The file's name, as the page shows it. */
  name: string;
  durationMs: number;
  poses: TimedPose[];
  frames: TimedFrame[];
  /** How many calls the file recorded (`/hal/calls`). */
  calls: number;
  /** The recorded robot's id, from the `hal.robot` metadata ('' when it has none). */
  deviceId: string;
  /** Where and why the file was not read whole (cut short, or damaged in part), if it was not. */
  truncation?: string;
}

/** Index of the last entry at or before `t` (-1 before the first). */
function lastAtOrBefore(entries: ReadonlyArray<{ t: number }>, t: number): number {
  let lo = 0;
  let hi = entries.length - 1;
  let found = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if ((entries[mid]?.t ?? Infinity) <= t) {
      found = mid;
      lo = mid + 1;
    } else hi = mid - 1;
  }
  return found;
}

/**
 * The pose at `t`: between two recorded poses, the straight line between them (yaw the short way
 * round); before the first, the first; after the last, the last. Undefined with no poses.
 */
export function poseAt(poses: readonly TimedPose[], t: number): Omit<TimedPose, 't'> | undefined {
  const i = lastAtOrBefore(poses, t);
  const a = poses[Math.max(i, 0)];
  if (a === undefined) return undefined;
  const b = poses[i + 1];
  if (i < 0 || b === undefined || b.t <= a.t) return { x: a.x, y: a.y, yaw: a.yaw };
  const k = (t - a.t) / (b.t - a.t);
  const turn = Math.atan2(Math.sin(b.yaw - a.yaw), Math.cos(b.yaw - a.yaw));
  return { x: a.x + (b.x - a.x) * k, y: a.y + (b.y - a.y) * k, yaw: a.yaw + turn * k };
}

/** The last camera frame recorded at or before `t` (undefined before the first). */
export function frameAt(frames: readonly TimedFrame[], t: number): TimedFrame | undefined {
  return frames[lastAtOrBefore(frames, t)];
}
