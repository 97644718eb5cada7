// The serving process's own CPU use, measured: the process's user and system CPU time over the
// wall time between two readings, in percent of one core (above 100 on several cores).

const MIN_WINDOW_MS = 250;

export class CpuMeter {
  #cpu = process.cpuUsage();
  #at = performance.now();
  #last = 0;

  /**
   * Percent of one core used since the previous reading; a reading under 250 ms after the last
   * one repeats it (a window that short is mostly noise).
   */
  percent(): number {
    const now = performance.now();
    const wallMs = now - this.#at;
    if (wallMs < MIN_WINDOW_MS && this.#last > 0) return this.#last;
    const used = process.cpuUsage(this.#cpu);
    this.#cpu = process.cpuUsage();
    this.#at = now;
    this.#last = wallMs > 0 ? ((used.user + used.system) / 1000 / wallMs) * 100 : 0;
    return this.#last;
  }
}
