/** What to draw on one animation frame. */
export interface FrameDraws {
  /** The 3D view (and the robots' labels over it). */
  view: boolean;
  /** What follows the scene: the robot's camera view and the trajectory plot. */
  scene: boolean;
}

/**
 * When the page draws: on demand, when the scene changed (its state string differs from the one
 * last drawn) or the view moved, and once per idle interval whatever happens; and never sooner
 * than the render profile's frame interval after the last frame drawn. A change that comes
 * within that interval is not lost: it is drawn on the first frame due.
 */
export class FrameSchedule {
  readonly #minIntervalMs: number;
  readonly #idleRedrawMs: number;
  /** The last frame drawn at all, ms. */
  #frameAt = Number.NEGATIVE_INFINITY;
  /** The last frame drawn for the scene, ms, and the scene's state then. */
  #sceneAt = Number.NEGATIVE_INFINITY;
  #scene: string | undefined;
  #framesDrawn = 0;

  constructor(options: { minIntervalMs: number; idleRedrawMs: number }) {
    this.#minIntervalMs = options.minIntervalMs;
    this.#idleRedrawMs = options.idleRedrawMs;
  }

  /** How many frames of the 3D view were drawn. */
  get framesDrawn(): number {
    return this.#framesDrawn;
  }

  /**
   * Notes a frame of the 3D view drawn out of turn, when the canvas was resized (which clears it:
   * see `Viewport.onResized`). It counts as a frame drawn; the times of the schedule stay as they
   * are, so the next frame due is drawn when it would have been.
   */
  drewOutOfTurn(): void {
    this.#framesDrawn += 1;
  }

  /** What to draw on the animation frame at `now` (ms), and notes it as drawn. */
  next(now: number, viewMoved: boolean, sceneState: string): FrameDraws {
    if (now - this.#frameAt < this.#minIntervalMs) return { view: false, scene: false };
    const scene = sceneState !== this.#scene || now - this.#sceneAt >= this.#idleRedrawMs;
    const view = viewMoved || scene;
    if (view) {
      this.#frameAt = now;
      this.#framesDrawn += 1;
    }
    if (scene) {
      this.#scene = sceneState;
      this.#sceneAt = now;
    }
    return { view, scene };
  }
}
