import { frameAt, poseAt } from './timeline.js';
import type { PlaybackTimeline, TimedFrame, TimedPose } from './timeline.js';

/** What a playback shows at its time: the pose and the camera frame recorded then. */
export interface PlaybackView {
  t: number;
  pose: Omit<TimedPose, 't'> | undefined;
  frame: TimedFrame | undefined;
}

/**
 * Plays a time line: play, pause, seek, and {@link tick} once per animation frame with the
 * page's clock (ms), which moves the time on while playing and stops at the end. Playing again
 * from the end starts over.
 */
export class Playback {
  readonly timeline: PlaybackTimeline;
  #t = 0;
  #playing = false;
  /** The page's clock at the last tick while playing. */
  #lastTick: number | undefined;

  constructor(timeline: PlaybackTimeline) {
    this.timeline = timeline;
  }

  get t(): number {
    return this.#t;
  }

  get playing(): boolean {
    return this.#playing;
  }

  play(): void {
    if (this.#t >= this.timeline.durationMs) this.#t = 0;
    this.#playing = true;
    this.#lastTick = undefined;
  }

  pause(): void {
    this.#playing = false;
  }

  /** Jumps to `t` ms (clamped to the time line). */
  seek(t: number): void {
    this.#t = Math.min(Math.max(Number.isFinite(t) ? t : 0, 0), this.timeline.durationMs);
    this.#lastTick = undefined;
  }

  /** Moves the time on by the page's clock since the last tick (while playing). */
  tick(now: number): void {
    if (!this.#playing) return;
    if (this.#lastTick !== undefined) this.#t += Math.max(0, now - this.#lastTick);
    this.#lastTick = now;
    if (this.#t >= this.timeline.durationMs) {
      this.#t = this.timeline.durationMs;
      this.#playing = false;
    }
  }

  /** What the scene and the camera panel show now. */
  view(): PlaybackView {
    return {
      t: this.#t,
      pose: poseAt(this.timeline.poses, this.#t),
      frame: frameAt(this.timeline.frames, this.#t),
    };
  }
}
