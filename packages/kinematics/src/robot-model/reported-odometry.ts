import type { RobotConfig } from '@hal/types';
import { integrateOdometry } from '../odometry.js';
import type { PlanarPoseCm } from '../odometry.js';
import type { WheelScale } from './wheel-scale.js';

/**
 * The pose the robot reports when its body differs from the nominal one (the simulator's body error):
 * dead reckoning from the wheels' step counts with the nominal geometry, as the firmware does,
 * each wheel's travel scaled by the odometry's error of the running motion. It is brought up to
 * the step counts whenever it is read and before every motion, so each stretch it integrates
 * belongs to one motion (a straight line, a turn on the spot or one arc: integrated exactly).
 */
export class ReportedOdometry {
  #pose: PlanarPoseCm;
  #left = 0;
  #right = 0;
  #scale: WheelScale = { left: 1, right: 1 };

  constructor(start: PlanarPoseCm) {
    this.#pose = { ...start };
  }

  /** Integrates the steps made since the last sync (absolute counts), with `config`. */
  sync(left: number, right: number, config: RobotConfig): void {
    const dl = left - this.#left;
    const dr = right - this.#right;
    this.#left = left;
    this.#right = right;
    if (dl === 0 && dr === 0) return;
    this.#pose = integrateOdometry(
      this.#pose,
      dl * this.#scale.left,
      dr * this.#scale.right,
      config,
    );
  }

  /** The next steps belong to a motion whose odometry errs by `scale`. */
  beginMotion(scale: WheelScale): void {
    this.#scale = scale;
  }

  get pose(): PlanarPoseCm {
    return { ...this.#pose };
  }
}
