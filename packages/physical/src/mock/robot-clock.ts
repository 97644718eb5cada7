/** The robot's own clock: time since it booted, running `timeScale` times faster than real time. */
export class RobotClock {
  readonly #now: () => number;
  readonly #timeScale: number;
  #bootAt: number;

  /** `now` is the real clock, ms. */
  constructor(now: () => number, timeScale: number) {
    this.#now = now;
    this.#timeScale = timeScale;
    this.#bootAt = now();
  }

  /** Robot time since boot, whole µs. */
  us(): number {
    return Math.floor((this.#now() - this.#bootAt) * 1000 * this.#timeScale);
  }

  /** Robot time since boot, whole ms. */
  uptimeMs(): number {
    return Math.floor(this.us() / 1000);
  }

  /** Boots again: uptime starts over from zero. */
  reboot(): void {
    this.#bootAt = this.#now();
  }
}
