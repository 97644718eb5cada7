/**
 * The host's e-stop latch: what a HAL (or a fleet) on this side of a link holds so that motion is
 * refused here at once, whatever the link does. An e-stop latches it before anything is sent; it
 * is cleared only by an accepted reset, or (see {@link EstopLatch.release}) once the far side
 * confirms it holds that same stop. It keeps the reason of the last e-stop.
 */
export class EstopLatch {
  #reason: string | undefined;

  /** True while latched. Synchronous, never throws. */
  get latched(): boolean {
    return this.#reason !== undefined;
  }

  /** The reason of the e-stop that latched it, while it is latched. */
  get reason(): string | undefined {
    return this.#reason;
  }

  /** Latches with `reason` (a later e-stop replaces the reason; it stays latched). */
  latch(reason: string): void {
    this.#reason = reason;
  }

  /** Clears it: an accepted reset. */
  reset(): void {
    this.#reason = undefined;
  }

  /**
   * Clears it if it still holds the e-stop of `reason` (the far side now holds that stop); a
   * newer e-stop with another reason keeps it latched. Returns whether it cleared.
   */
  release(reason: string): boolean {
    if (this.#reason !== reason) return false;
    this.#reason = undefined;
    return true;
  }
}
