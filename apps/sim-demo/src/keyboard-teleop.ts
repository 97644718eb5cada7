import type { SimulationHAL } from '@hal/simulation';
import type { GoalDriver } from './goal-driver.js';
import type { ResultsLog } from './results-log.js';
import type { StatusLine } from './status-line.js';
import { powersFor, TELEOP_KEYS } from './teleop.js';

export interface KeyboardTeleopOptions {
  hal: SimulationHAL;
  goals: GoalDriver;
  log: ResultsLog;
  status: StatusLine;
  /** While this answers true (a recording playing back), keys do not drive. */
  paused?: () => boolean;
}

function keyName(e: KeyboardEvent): string {
  return e.key.length === 1 ? e.key.toLowerCase() : e.key;
}

/**
 * Drives the robot from the keyboard: arrow keys or WASD `drive` while held and `stop` on
 * release; Space stops (and cancels a goal). Keys in a menu are left to the menu.
 */
export class KeyboardTeleop {
  readonly #options: KeyboardTeleopOptions;
  readonly #held = new Set<string>();
  /** The wheel powers last sent, as JSON ('' when nothing is known to be sent). */
  #lastDrive = '';
  /**
   * Teleop actions run one after another, each for the keys held when it runs, so a quick
   * release can never be overtaken by the drive it ends.
   */
  #chain: Promise<void> = Promise.resolve();

  constructor(options: KeyboardTeleopOptions) {
    this.#options = options;
  }

  /** Listens to the keys of `target` (the page's window). */
  attach(target: Window): void {
    target.addEventListener('keydown', (e) => this.#keyDown(e));
    target.addEventListener('keyup', (e) => {
      if (this.#held.delete(keyName(e))) this.#apply();
    });
    target.addEventListener('blur', () => {
      if (this.#held.size === 0) return;
      this.#held.clear();
      this.#apply();
    });
  }

  /** Forgets the keys held (they no longer drive until pressed again). */
  releaseKeys(): void {
    this.#held.clear();
  }

  /** Forgets what was last sent, so the next key sends its drive whatever it is. */
  forgetLastDrive(): void {
    this.#lastDrive = '';
  }

  #keyDown(e: KeyboardEvent): void {
    if (e.target instanceof HTMLSelectElement || this.#options.paused?.() === true) return;
    const key = keyName(e);
    if (key === ' ') {
      e.preventDefault();
      const { hal, goals, log, status } = this.#options;
      this.#held.clear();
      this.#lastDrive = 'null';
      void hal.locomotion.stop().then((r) => log.record('stop()', r));
      void goals.cancel();
      status.set('Stopped');
      return;
    }
    if (!TELEOP_KEYS.has(key)) return;
    e.preventDefault();
    if (!this.#held.has(key)) {
      this.#held.add(key);
      this.#apply();
    }
  }

  #apply(): void {
    this.#chain = this.#chain.then(() => this.#driveNow()).catch(() => undefined);
  }

  async #driveNow(): Promise<void> {
    const { hal, goals, log, status } = this.#options;
    const powers = powersFor(this.#held);
    const signature = JSON.stringify(powers ?? null);
    if (signature === this.#lastDrive) return;
    this.#lastDrive = signature;
    if (powers === undefined) {
      log.record('stop()', await hal.locomotion.stop());
      status.set('Stopped');
      return;
    }
    if (goals.state === 'driving') await goals.cancel();
    status.set(`Driving: left ${powers.left}, right ${powers.right}`);
    const result = await hal.locomotion.drive(powers.left, powers.right);
    if (!result.success) {
      log.record(`drive(${powers.left}, ${powers.right})`, result);
      status.set(`${result.code}: ${result.error ?? ''}`, 'bad');
    }
  }
}
