import type {
  DecisionContext,
  DecisionProvider,
  NavigationDecision,
  Point,
  Pose2D,
} from '@hal/navigation';
import type { ObjectMemory, RememberedObject } from '@hal/perception';
import { mostPromisingFrontier } from './frontier-choice.js';
import type { NamedObject } from './named-object.js';
import { wrapDeg } from './seen-thing.js';

/** Options of an {@link ObjectSeekingProvider}. */
export interface ObjectSeekerOptions {
  /** What to find. */
  target: NamedObject;
  /** Where perception remembers what it saw (the bridge's observer fills it). */
  memory: ObjectMemory;
  /**
   * How far from the object's surface to aim the robot's centre, metres. Default 0.17: the
   * guard's default stand-off (0.1 m ahead of the front) plus the V1's half length (0.07).
   */
  standOffM?: number;
  /**
   * Stop once the object's surface is estimated this near, metres. Default the instruction's
   * "within" distance (0.25 when it gives none) less 0.04, for the estimate's error.
   */
  stopWithinM?: number;
  /** The turn between two looks when looking round, degrees. Default 60 (the camera sees 62). */
  scanStepDeg?: number;
  /**
   * Look round again at each frontier reached. Default false: the camera looks where the robot
   * drives, so driving to the next frontier shows more for the calls than turning in place.
   */
  lookRoundAgain?: boolean;
  /** Legs driven toward a frontier before choosing another (a turn to face one counts). Default 4. */
  exploreLegs?: number;
  /**
   * How much frontiers the way the robot first faced are favoured: a frontier's promise is
   * weighted by 1 + this x the cosine of its bearing off that heading. Default 0.3; 0 for none.
   */
  aheadWeight?: number;
}

/** Where the search stands, for the agent's answer. */
export type SeekPhase = 'looking' | 'exploring' | 'approaching' | 'arrived' | 'not-found';

const DEG = Math.PI / 180;
const f2 = (v: number) => v.toFixed(2);

/** Closer than this to where the last approach began, metres: the approach made no progress. */
const NO_PROGRESS_M = 0.02;
/** Turned less than this since then, radians: no progress either. */
const NO_TURN = 2 * (Math.PI / 180);
/** This near a frontier chosen, metres, the robot is there. */
const ARRIVED_M = 0.3;

/**
 * Finds a named object with the camera and stops before it. Each cycle, after the bridge's
 * observer has laid the frame into the grid and the memory: when the memory holds the object, it
 * goes to a point `standOffM` in front of its estimated surface (the bridge plans on the grid the
 * camera mapped; the next cycle re-estimates and re-plans), and stops once the surface is within
 * `stopWithinM` (or the guard holds the robot just before it); when it does not, it looks round
 * (turning in place `scanStepDeg` at a time), then drives to the most promising frontier of what
 * it has seen ({@link mostPromisingFrontier}, favouring the way it first faced), and the next,
 * looking where it drives. It never gets the object's position from anywhere but the memory.
 */
export class ObjectSeekingProvider implements DecisionProvider {
  readonly name = 'object-seeking';
  readonly #target: NamedObject;
  readonly #memory: ObjectMemory;
  readonly #standOffM: number;
  readonly #stopWithinM: number;
  readonly #withinM: number;
  readonly #scanStep: number;
  readonly #turnsPerCircle: number;
  readonly #exploreLegs: number;
  #turns = 0;
  readonly #lookRoundAgain: boolean;
  readonly #aheadWeight: number;
  #legs = 0;
  #frontier: Point | undefined;
  #firstHeading: number | undefined;
  #lastApproach: Pose2D | undefined;
  #stalls = 0;
  readonly #abandoned: Point[] = [];
  /** Where the search stands. */
  phase: SeekPhase = 'looking';
  /** The object as last estimated, when found. */
  found: RememberedObject | undefined;

  constructor(options: ObjectSeekerOptions) {
    this.#target = options.target;
    this.#memory = options.memory;
    this.#standOffM = options.standOffM ?? 0.17;
    const within = options.target.withinM ?? 0.25;
    this.#withinM = within;
    this.#stopWithinM = options.stopWithinM ?? within - 0.04;
    this.#scanStep = (options.scanStepDeg ?? 60) * DEG;
    this.#turnsPerCircle = Math.ceil((2 * Math.PI) / this.#scanStep - 1e-9);
    this.#exploreLegs = options.exploreLegs ?? 4;
    this.#lookRoundAgain = options.lookRoundAgain ?? false;
    this.#aheadWeight = options.aheadWeight ?? 0.3;
    if (!(this.#aheadWeight >= 0 && this.#aheadWeight < 1))
      throw new RangeError(`"aheadWeight" must be 0 or more and under 1, got ${this.#aheadWeight}`);
    for (const [name, v] of [
      ['standOffM', this.#standOffM],
      ['stopWithinM', this.#stopWithinM],
      ['scanStepDeg', this.#scanStep],
      ['exploreLegs', this.#exploreLegs],
    ] as const) {
      if (!(v > 0 && Number.isFinite(v)))
        throw new RangeError(`"${name}" must be a positive number, got ${v}`);
    }
  }

  /**
   * The object as the memory has it now: of the remembered objects of its colour, one of the
   * named kind first, then one whose kind is unknown, then any (a kind can be misread from afar);
   * among those the most often seen.
   */
  estimate(): RememberedObject | undefined {
    const rank = (o: RememberedObject) =>
      o.kind === this.#target.kind ? 0 : o.kind === 'unknown' ? 1 : 2;
    const candidates = this.#memory.find(this.#target.colour ?? this.#target.query);
    return candidates.sort((a, b) => rank(a) - rank(b) || b.timesSeen - a.timesSeen)[0];
  }

  async decide(context: DecisionContext): Promise<NavigationDecision> {
    const { pose } = context;
    // where the robot first faced: the way it was set going, favoured among frontiers
    this.#firstHeading ??= pose.yaw;
    const object = this.estimate();
    if (object !== undefined) return this.#approach(context, object);
    // Drive on toward the frontier chosen until there (or its legs are spent), then look round.
    const goal = this.#frontier;
    if (goal !== undefined) {
      const there = Math.hypot(pose.x - goal.x, pose.y - goal.y) <= ARRIVED_M;
      const blocked = context.grid.stateAt(goal.x, goal.y) === 'occupied';
      if (there || blocked || this.#legs >= this.#exploreLegs) {
        this.#abandoned.push(goal);
        this.#frontier = undefined;
        if (this.#lookRoundAgain) this.#turns = 0;
      } else {
        this.#legs += 1;
        return this.#explore(goal);
      }
    }
    if (this.#turns < this.#turnsPerCircle - 1) {
      this.#turns += 1;
      this.phase = 'looking';
      const yaw = wrapDeg((pose.yaw + this.#scanStep) / DEG);
      return {
        reasoning: `No ${this.#target.query} seen yet: turning to look (view ${this.#turns + 1} of ${this.#turnsPerCircle}).`,
        action: { type: 'ROTATE_TO', yaw_deg: yaw },
        goal_reached: false,
      };
    }
    const frontier = mostPromisingFrontier(context.grid, pose, {
      exclude: this.#abandoned,
      heading: this.#firstHeading,
      headingWeight: this.#aheadWeight,
    });
    if (frontier === undefined) {
      this.phase = 'not-found';
      return {
        reasoning: `Looked everywhere I can reach and saw no ${this.#target.query}.`,
        action: { type: 'STOP' },
        goal_reached: false,
      };
    }
    this.#frontier = frontier.target;
    this.#legs = 1;
    return this.#explore(frontier.target);
  }

  #explore(goal: Point): NavigationDecision {
    this.phase = 'exploring';
    return {
      reasoning: `No ${this.#target.query} seen yet: exploring toward (${f2(goal.x)}, ${f2(goal.y)}).`,
      action: { type: 'MOVE_TO', x: goal.x, y: goal.y },
      goal_reached: false,
    };
  }

  #approach(context: DecisionContext, object: RememberedObject): NavigationDecision {
    const { pose } = context;
    this.found = object;
    const radius = Math.min(0.25, Math.max(0.05, object.widthM / 2));
    const away = Math.hypot(pose.x - object.x, pose.y - object.y);
    const surface = away - radius;
    const where = `${object.id} at (${f2(object.x)}, ${f2(object.y)}), ${f2(surface)} m from its surface`;
    // The guard stopped the last leg before what is ahead: the object, when it is this near.
    const held = context.lastResult?.code === 'OBSTACLE_AHEAD' && surface <= this.#withinM + 0.15;
    if (surface <= this.#stopWithinM || held) {
      this.phase = 'arrived';
      return {
        reasoning: held
          ? `Stopped before the ${where}: the guard holds the robot here.`
          : `Stopped before the ${where}.`,
        action: { type: 'STOP' },
        goal_reached: true,
      };
    }
    // Driving toward it left the robot where it was twice: it cannot get nearer from here.
    const last = this.#lastApproach;
    const still =
      last !== undefined &&
      Math.hypot(pose.x - last.x, pose.y - last.y) < NO_PROGRESS_M &&
      Math.abs(Math.atan2(Math.sin(pose.yaw - last.yaw), Math.cos(pose.yaw - last.yaw))) < NO_TURN;
    this.#stalls = still ? this.#stalls + 1 : 0;
    this.#lastApproach = { x: pose.x, y: pose.y, yaw: pose.yaw };
    if (this.#stalls >= 3) {
      const near = surface <= this.#withinM;
      this.phase = near ? 'arrived' : 'not-found';
      return {
        reasoning: `Cannot get nearer to the ${where}.`,
        action: { type: 'STOP' },
        goal_reached: near,
      };
    }
    this.phase = 'approaching';
    const ux = away > 1e-6 ? (pose.x - object.x) / away : 1;
    const uy = away > 1e-6 ? (pose.y - object.y) / away : 0;
    const stand = radius + this.#standOffM;
    const x = object.x + ux * stand;
    const y = object.y + uy * stand;
    return {
      reasoning: `Saw the ${where}: going to (${f2(x)}, ${f2(y)}) in front of it.`,
      action: { type: 'MOVE_TO', x, y },
      goal_reached: false,
    };
  }
}
