import { OccupancyGrid } from '@hal/navigation';
import type { Pose2D } from '@hal/navigation';
import { ObjectMemory, Perception } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { SkillPose } from './skill-result.js';

/** Options of a skill set (see {@link createSkills}). */
export interface SkillOptions {
  /** The memory of what was seen; default a new one (shared by every skill of the set). */
  memory?: ObjectMemory;
  /** The map the camera builds; default a 10 m square at 5 cm round the odometry origin. */
  grid?: OccupancyGrid;
  /** Perception over the same HAL, memory and grid; default one made here. */
  perception?: Perception;
  /**
   * How far from an object's surface `go_to` stops, metres. Default 0.17: the guard's default
   * stand-off (0.1 m ahead of the front) plus the V1's half length.
   */
  standOffM?: number;
  /** How near a point counts as reached by `go_to` and `go_back`, metres. Default 0.04. */
  pointToleranceM?: number;
  /** Longest leg `go_to` drives between two looks, metres. Default 1.2 (the camera sees ~2.5 m). */
  maxLegM?: number;
  /** Most look-and-drive cycles in one `go_to`, `go_back` or `explore`. Default 60. */
  maxCycles?: number;
}

/** What every skill of one set shares: the robot, what it has seen and where it started. */
export class SkillContext {
  readonly hal: HardwareAbstractionLayer;
  readonly memory: ObjectMemory;
  readonly grid: OccupancyGrid;
  readonly perception: Perception;
  readonly standOffM: number;
  readonly pointToleranceM: number;
  readonly maxLegM: number;
  readonly maxCycles: number;
  /** Aborts when a stop or an e-stop interrupts the skill running (see SkillSet.interrupt). */
  signal: AbortSignal | undefined;
  /** The longest motion the leash was found to allow, metres (learnt from a refusal). */
  leashLegM: number | undefined;
  #start: Pose2D | undefined;

  constructor(hal: HardwareAbstractionLayer, options: SkillOptions = {}) {
    this.hal = hal;
    this.memory = options.perception?.memory ?? options.memory ?? new ObjectMemory();
    // a little more room round what the camera saw than the default: a wall's end seen side-on
    // is thin in the image, and the guard stops a leg that passes a corner too near
    this.grid =
      options.perception?.grid ??
      options.grid ??
      new OccupancyGrid({ widthM: 10, heightM: 10, clearanceM: 0.08 });
    this.perception =
      options.perception ?? new Perception(hal, { memory: this.memory, grid: this.grid });
    this.standOffM = positive('standOffM', options.standOffM ?? 0.17);
    this.pointToleranceM = positive('pointToleranceM', options.pointToleranceM ?? 0.04);
    this.maxLegM = positive('maxLegM', options.maxLegM ?? 1.2);
    this.maxCycles = positive('maxCycles', options.maxCycles ?? 60);
  }

  /** The believed pose now (odometry); the first one read is where the run started. */
  async pose(): Promise<Pose2D> {
    const pose = await this.perception.pose();
    this.#start ??= pose;
    return pose;
  }

  /** Whether a stop interrupted the skill running: it must not start another motion. */
  interrupted(): boolean {
    return this.signal?.aborted === true;
  }

  /** The longest leg a drive may take now: `maxLegM`, or less where the leash allows less. */
  legM(): number {
    return Math.min(this.maxLegM, this.leashLegM ?? Number.POSITIVE_INFINITY);
  }

  /** Where the run started: the pose the first skill read. */
  async start(): Promise<Pose2D> {
    return this.#start ?? (await this.pose());
  }

  /** Marks `pose` as where the run started, unless a start is known already. */
  markStart(pose: Pose2D): void {
    this.#start ??= pose;
  }
}

/** A pose as skills report it: metres to the centimetre, degrees to the degree. */
export function skillPose(pose: Pose2D): SkillPose {
  return {
    x: Math.round(pose.x * 100) / 100,
    y: Math.round(pose.y * 100) / 100,
    yawDeg: Math.round((pose.yaw * 180) / Math.PI),
  };
}

function positive(name: string, value: number): number {
  if (!(value > 0 && Number.isFinite(value)))
    throw new RangeError(`"${name}" must be a positive number, got ${value}`);
  return value;
}
