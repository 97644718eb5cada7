import { StepAccumulator } from '../steps.js';
import type { RobotConfig } from '@hal/types';

/**
 * A wheel's step accumulator that can take back its last addition, for a command the step limit
 * refuses (the firmware peeks before it commits; a refused command leaves the carry unchanged).
 */
export class WheelAccumulator {
  #acc: StepAccumulator;
  #history: number[] = [];
  readonly #config: () => RobotConfig;

  constructor(config: () => RobotConfig) {
    this.#config = config;
    this.#acc = new StepAccumulator(config());
  }

  /** Adds a distance, cm; returns the whole steps to make for it. */
  add(cm: number): number {
    this.#history.push(cm);
    return this.#acc.add(cm);
  }

  /** Forgets the last {@link add} (rare: only a refused command needs it). */
  undo(): void {
    this.#history.pop();
    this.#acc = new StepAccumulator(this.#config());
    for (const cm of this.#history) this.#acc.add(cm);
  }

  /** Forgets every addition and the carry (`hello`, `set_config`). */
  reset(): void {
    this.#acc = new StepAccumulator(this.#config());
    this.#history = [];
  }
}
