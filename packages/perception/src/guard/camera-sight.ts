import { nearestVisibleFloorM } from '@hal/kinematics';
import type { HardwareAbstractionLayer } from '@hal/types';
import { clearanceAhead } from '../clearance.js';
import { decodeFrame } from '../decode.js';
import type { FramePerceiver } from '../frame-perceiver.js';
import { bounded } from './bounded.js';
import type { Sight, Sighting } from './sighting.js';
import { viewFilled } from './view-filled.js';

/** Where the perceiver's pose is irrelevant: free space is in the robot's frame. */
const ORIGIN = { x: 0, y: 0, yaw: 0 };

/**
 * Looks ahead with the camera: a frame (`captureFrame`), its free space through a
 * {@link FramePerceiver}, the clearance of the corridor ahead. One look at a time (looks asked
 * for together wait their turn, each on a frame taken after it was asked for). A view that an
 * obstacle fills (so the floor model learnt it as floor) is seen as blocked at the edge of the
 * camera's blind zone, and the floor is learnt again from the next frame.
 */
export class CameraSight implements Sight {
  readonly source = 'camera' as const;
  readonly #hal: HardwareAbstractionLayer;
  readonly #makePerceiver: () => FramePerceiver;
  readonly #bodyRadiusM: number;
  readonly #halfWidthM: number;
  readonly #timeoutMs: number;
  #perceiver: FramePerceiver;
  #turn: Promise<unknown> = Promise.resolve();

  constructor(
    hal: HardwareAbstractionLayer,
    makePerceiver: () => FramePerceiver,
    geometry: { bodyRadiusM: number; halfWidthM: number; timeoutMs: number },
  ) {
    this.#hal = hal;
    this.#makePerceiver = makePerceiver;
    this.#perceiver = makePerceiver();
    this.#bodyRadiusM = geometry.bodyRadiusM;
    this.#halfWidthM = geometry.halfWidthM;
    this.#timeoutMs = geometry.timeoutMs;
  }

  /** How far ahead of the body's front the camera's view of the floor begins, metres. */
  get blindZoneM(): number {
    return Math.max(0, nearestVisibleFloorM(this.#perceiver.projection) - this.#bodyRadiusM);
  }

  look(): Promise<Sighting> {
    const next = this.#turn.then(
      () => this.#lookNow(),
      () => this.#lookNow(),
    );
    this.#turn = next.catch(() => undefined);
    return next;
  }

  async #lookNow(): Promise<Sighting> {
    const frame = await bounded(this.#hal.vision.captureFrame(), this.#timeoutMs, 'camera frame');
    const image = await decodeFrame(frame);
    const perceiver = this.#perceiver;
    const percept = await perceiver.perceiveImage(image, ORIGIN);
    if (viewFilled(perceiver, image)) {
      this.#perceiver = this.#makePerceiver();
      return {
        aheadM: this.blindZoneM,
        blocked: true,
        atEdge: true,
        source: 'camera',
        at: Date.now(),
      };
    }
    const clearance = clearanceAhead(percept.freeSpace, this.#bodyRadiusM, this.#halfWidthM);
    const atEdge = percept.freeSpace.some(
      (column) => column.hit && column.atEdge && Math.abs(column.to.y) <= this.#halfWidthM,
    );
    return {
      aheadM: clearance.aheadM,
      blocked: clearance.blocked,
      atEdge,
      source: 'camera',
      at: Date.now(),
    };
  }
}
