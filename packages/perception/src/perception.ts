import type { OccupancyGrid, Pose2D } from '@hal/navigation';
import { HalError, withTimeout } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { FramePerceiver } from './frame-perceiver.js';
import type { FramePerceiverOptions, Percept } from './frame-perceiver.js';
import { integrateFreeSpace } from './grid-fusion.js';
import { ObjectMemory } from './object-memory.js';
import type { ObjectMemoryOptions, RememberedObject } from './object-memory.js';

/** Options of {@link Perception}. */
export interface PerceptionOptions extends FramePerceiverOptions {
  /** The memory of what was seen, or its options. Default a new one. */
  memory?: ObjectMemory | ObjectMemoryOptions;
  /** A grid to lay each frame's free space into (the navigation bridge's world model). */
  grid?: OccupancyGrid;
  /** Longest wait for a frame or a pose, ms. Default 5000. */
  timeoutMs?: number;
  /** The robot's body radius, metres (clearances are from its edge). Default 0.07 (V1). */
  bodyRadiusM?: number;
}

/** One look: what the frame showed, and what the memory made of its objects. */
export interface Look extends Percept {
  /** The remembered objects this frame's sightings were merged into, in the order of `objects`. */
  remembered: RememberedObject[];
}

/**
 * Perception bound to a HAL: each `look()` reads the pose, captures a frame, finds objects and
 * free space in it, remembers the objects and lays the free space into the grid. It uses only
 * the HAL's public calls, so it is the same over the simulator and the physical robot.
 */
export class Perception {
  readonly hal: HardwareAbstractionLayer;
  readonly perceiver: FramePerceiver;
  readonly memory: ObjectMemory;
  readonly grid: OccupancyGrid | undefined;
  readonly bodyRadiusM: number;
  readonly #timeoutMs: number;
  readonly #listeners = new Set<(look: Look) => void>();

  constructor(hal: HardwareAbstractionLayer, options: PerceptionOptions = {}) {
    this.hal = hal;
    // the camera the robot reports (its configuration or calibration) unless one is given
    const camera = options.camera ?? hal.getDeviceInfo().camera;
    this.perceiver = new FramePerceiver(camera === undefined ? options : { ...options, camera });
    this.memory =
      options.memory instanceof ObjectMemory ? options.memory : new ObjectMemory(options.memory);
    this.grid = options.grid;
    this.#timeoutMs = options.timeoutMs ?? 5000;
    this.bodyRadiusM = options.bodyRadiusM ?? 0.07;
    if (!(this.bodyRadiusM >= 0 && Number.isFinite(this.bodyRadiusM)))
      throw new RangeError(`"bodyRadiusM" must be 0 or more, got ${this.bodyRadiusM}`);
    if (!(this.#timeoutMs > 0 && Number.isFinite(this.#timeoutMs)))
      throw new RangeError(`"timeoutMs" must be a positive number, got ${this.#timeoutMs}`);
  }

  /** The robot's believed pose now (odometry), as a 2D pose. */
  async pose(): Promise<Pose2D> {
    const answer = await withTimeout(this.hal.locomotion.getPose(), this.#timeoutMs);
    if (answer === undefined) {
      throw new HalError('TIMEOUT', `getPose gave no answer within ${this.#timeoutMs} ms`);
    }
    const { position, rotation } = answer.value;
    return { x: position.x, y: position.y, yaw: rotation.yaw };
  }

  /** Looks once: the pose, a frame, what it shows; remembered and mapped. */
  async look(): Promise<Look> {
    const pose = await this.pose();
    const capturedAt = Date.now();
    const frame = await withTimeout(this.hal.vision.captureFrame(), this.#timeoutMs);
    if (frame === undefined) {
      throw new HalError('TIMEOUT', `captureFrame gave no frame within ${this.#timeoutMs} ms`);
    }
    const percept = await this.perceiver.perceive(frame.value, pose, capturedAt);
    const remembered = this.memory.remember(percept.objects, capturedAt);
    if (this.grid !== undefined) integrateFreeSpace(this.grid, pose, percept.freeSpace);
    const look: Look = { ...percept, remembered };
    for (const listener of this.#listeners) listener(look);
    return look;
  }

  /** The remembered objects that fit `query` ("red box", "pillar"; empty: all). */
  where(query = ''): RememberedObject[] {
    return this.memory.find(query);
  }

  /** Calls `listener` after every look (for recording and live views); returns the unsubscriber. */
  onLook(listener: (look: Look) => void): () => void {
    this.#listeners.add(listener);
    return () => this.#listeners.delete(listener);
  }
}
