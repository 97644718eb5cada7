import type { ColourName } from './palette.js';
import type { ObjectKind, SeenObject } from './seen-object.js';

/** One object the robot remembers, merged from every sighting of it. World (odometry) frame. */
export interface RememberedObject {
  /** A name for it that carries no world knowledge: its label and a number, e.g. "red box 1". */
  id: string;
  colour: ColourName;
  kind: ObjectKind;
  label: string;
  /** Its estimated centre, metres (a weighted mean of its sightings). */
  x: number;
  y: number;
  /** One standard deviation of the estimate, metres. */
  uncertaintyM: number;
  /** Its width across the line of sight, metres (the mean of its sightings). */
  widthM: number;
  /** How many sightings were merged into it. */
  timesSeen: number;
  /** When it was first and last seen, ms since the epoch. */
  firstSeenAt: number;
  lastSeenAt: number;
}

/** Options of an {@link ObjectMemory}. */
export interface ObjectMemoryOptions {
  /** Sightings of the same colour (and kind, where both know it) within this are one, m. Default 0.35. */
  mergeRadiusM?: number;
  /** Sightings below this confidence are not remembered. Default 0.3. */
  minConfidence?: number;
}

/** A sighting's standard deviation, metres: grows with distance (one image row spans more). */
function sightingSigma(object: SeenObject): number {
  const base = 0.02 + 0.03 * object.distanceM * object.distanceM;
  return object.partial.length > 0 ? base * 2 : base;
}

/**
 * What the robot has seen: objects merged across frames and poses (the same colour and kind
 * within a radius is one object), each with its position, uncertainty, when it was last seen and
 * how often. Queryable by words ("red box", "pillar", "green"), cleared on request.
 */
export class ObjectMemory {
  readonly #objects: RememberedObject[] = [];
  readonly #counters = new Map<string, number>();
  readonly #mergeRadiusM: number;
  readonly #minConfidence: number;

  constructor(options: ObjectMemoryOptions = {}) {
    this.#mergeRadiusM = options.mergeRadiusM ?? 0.35;
    this.#minConfidence = options.minConfidence ?? 0.3;
    if (!(this.#mergeRadiusM > 0 && Number.isFinite(this.#mergeRadiusM)))
      throw new RangeError(`"mergeRadiusM" must be a positive number, got ${this.#mergeRadiusM}`);
    if (!(this.#minConfidence >= 0 && this.#minConfidence <= 1))
      throw new RangeError(`"minConfidence" must be 0..1, got ${this.#minConfidence}`);
  }

  /** Everything remembered, most recently seen first. */
  all(): RememberedObject[] {
    return [...this.#objects]
      .sort((a, b) => b.lastSeenAt - a.lastSeenAt || a.id.localeCompare(b.id))
      .map((o) => ({ ...o }));
  }

  /** How many objects are remembered. */
  get size(): number {
    return this.#objects.length;
  }

  /** Forgets everything. */
  clear(): void {
    this.#objects.length = 0;
    this.#counters.clear();
  }

  /** Merges one frame's sightings, taken at `at` (ms since the epoch). Returns what they became. */
  remember(objects: readonly SeenObject[], at: number): RememberedObject[] {
    const touched: RememberedObject[] = [];
    for (const seen of objects) {
      if (seen.confidence < this.#minConfidence) continue;
      const match = this.#nearestMatch(seen);
      const sigma = sightingSigma(seen);
      if (match === undefined) {
        const count = (this.#counters.get(seen.label) ?? 0) + 1;
        this.#counters.set(seen.label, count);
        const created: RememberedObject = {
          id: `${seen.label} ${count}`,
          colour: seen.colour,
          kind: seen.kind,
          label: seen.label,
          x: seen.world.x,
          y: seen.world.y,
          uncertaintyM: sigma,
          widthM: seen.widthM,
          timesSeen: 1,
          firstSeenAt: at,
          lastSeenAt: at,
        };
        this.#objects.push(created);
        touched.push(created);
        continue;
      }
      // Inverse-variance weighting of the estimate and the new sighting.
      const wOld = 1 / (match.uncertaintyM * match.uncertaintyM);
      const wNew = 1 / (sigma * sigma);
      match.x = (match.x * wOld + seen.world.x * wNew) / (wOld + wNew);
      match.y = (match.y * wOld + seen.world.y * wNew) / (wOld + wNew);
      match.uncertaintyM = Math.sqrt(1 / (wOld + wNew));
      match.widthM = (match.widthM * match.timesSeen + seen.widthM) / (match.timesSeen + 1);
      match.timesSeen += 1;
      match.lastSeenAt = Math.max(match.lastSeenAt, at);
      if (match.kind === 'unknown' && seen.kind !== 'unknown') {
        match.kind = seen.kind;
        match.label = seen.label;
      }
      touched.push(match);
    }
    return touched.map((o) => ({ ...o }));
  }

  /**
   * The remembered objects that fit `query` (words: a colour, a kind, an id; "red box",
   * "the green pillar", "red box 2"), most often seen first. An empty query matches everything.
   */
  find(query: string): RememberedObject[] {
    const words = query
      .toLowerCase()
      .replace(/[^a-z0-9 ]/g, ' ')
      .split(/\s+/)
      .filter((w) => w !== '' && w !== 'the' && w !== 'a' && w !== 'an' && w !== 'object');
    const kindWords: Record<string, ObjectKind> = {
      box: 'box',
      boxes: 'box',
      cube: 'box',
      pillar: 'pillar',
      pillars: 'pillar',
      cylinder: 'pillar',
      post: 'pillar',
    };
    return this.all()
      .filter((o) => {
        const idNumber = o.id.split(' ').at(-1);
        return words.every(
          (w) =>
            w === o.colour ||
            (kindWords[w] !== undefined && (kindWords[w] === o.kind || o.kind === 'unknown')) ||
            w === idNumber,
        );
      })
      .sort((a, b) => b.timesSeen - a.timesSeen || b.lastSeenAt - a.lastSeenAt);
  }

  #nearestMatch(seen: SeenObject): RememberedObject | undefined {
    let best: RememberedObject | undefined;
    let bestDistance = this.#mergeRadiusM;
    for (const o of this.#objects) {
      if (o.colour !== seen.colour) continue;
      if (o.kind !== 'unknown' && seen.kind !== 'unknown' && o.kind !== seen.kind) continue;
      const d = Math.hypot(o.x - seen.world.x, o.y - seen.world.y);
      if (d <= bestDistance) {
        bestDistance = d;
        best = o;
      }
    }
    return best;
  }
}
