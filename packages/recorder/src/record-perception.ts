/*
 * Records what perception believed beside where the robot was: after every look, the remembered
 * objects (`/perception/objects`), the frame's sightings (`/perception/detections`), both as
 * foxglove.SceneUpdate, and the occupancy grid (`/perception/grid`, foxglove.Grid) when it changed.
 * A look never waits for it: the listener only takes what the look handed over and defers the
 * rest to the recording's background work; a full queue drops and counts, as every channel does.
 */
import { SCENE_UPDATE, GRID } from './foxglove-scene-schemas.js';
import { robotNamespace } from './namespace.js';
import { gridMessage, objectsScene, sightingsScene } from './perception-messages.js';
import type { PerceivedGrid, PerceivedObject, PerceivedSighting } from './perception-messages.js';
import type { McapRecorder } from './recorder.js';

/** What one look hands over (a `Look` of @hal/perception). */
export interface PerceivedLook {
  /** When the frame was taken, ms since the epoch. */
  capturedAt: number;
  /** The frame's sightings. */
  objects: readonly PerceivedSighting[];
  /** The remembered objects the sightings became. */
  remembered: readonly PerceivedObject[];
}

/** What {@link recordPerception} records (a @hal/perception `Perception` is one). */
export interface RecordablePerception {
  /** Calls `listener` after every look; returns the unsubscriber. */
  onLook(listener: (look: PerceivedLook) => void): () => void;
  /** Everything remembered. */
  readonly memory: { all(): PerceivedObject[] };
  /** The grid its looks are laid into, if any. */
  readonly grid?: PerceivedGrid | undefined;
}

/** Options of {@link recordPerception}. */
export interface RecordPerceptionOptions {
  /** The grid to record (default the perception's own, if it has one). */
  grid?: PerceivedGrid;
  /** The robot's namespace in a recording of several (topics under `/<namespace>`). */
  namespace?: string;
  /** Write the grid at most this often, ms (it is written only when it changed). Default 1000. */
  gridPeriodMs?: number;
}

/** The perception topics of a robot (under `/<namespace>` in a recording of several). */
export const PERCEPTION_TOPICS = Object.freeze({
  objects: '/perception/objects',
  detections: '/perception/detections',
  grid: '/perception/grid',
});

/** A running perception recording. */
export interface PerceptionRecording {
  /** Looks seen so far. */
  readonly looks: number;
  /**
   * Looks left out because {@link MAX_PENDING_LOOKS} were already waiting for the recording's
   * background work (a recording that cannot keep up loses looks, never delays them).
   */
  readonly skipped: number;
  /** Stops recording (the topics already written stay). */
  stop(): void;
}

/** Looks waiting to be written, at most; more are skipped and counted. */
export const MAX_PENDING_LOOKS = 16;

/** How far (m) a sighting may lie from the object it became for its height to count as that object's. */
const SAME_OBJECT_M = 0.5;

/**
 * Records `perception`'s looks into `recorder` (see the file comment for the topics). World
 * positions are in the frame of the recorded pose (`world`, the robot's odometry).
 */
export function recordPerception(
  recorder: McapRecorder,
  perception: RecordablePerception,
  options: RecordPerceptionOptions = {},
): PerceptionRecording {
  const gridPeriodMs = options.gridPeriodMs ?? 1000;
  if (!(gridPeriodMs >= 0 && Number.isFinite(gridPeriodMs))) {
    throw new RangeError(`"gridPeriodMs" must be 0 or more, got ${gridPeriodMs}`);
  }
  const space = robotNamespace(options.namespace);
  const prefix = space.namespace === undefined ? '' : `/${space.namespace}`;
  const topics = {
    objects: `${prefix}${PERCEPTION_TOPICS.objects}`,
    detections: `${prefix}${PERCEPTION_TOPICS.detections}`,
    grid: `${prefix}${PERCEPTION_TOPICS.grid}`,
  };
  const grid = options.grid ?? perception.grid;
  recorder.channel(topics.objects, SCENE_UPDATE);
  recorder.channel(topics.detections, SCENE_UPDATE);
  if (grid !== undefined) recorder.channel(topics.grid, GRID);

  /** The height each remembered object was last seen with (the memory keeps only its width). */
  const heights = new Map<string, number>();
  let gridVersion = -1;
  let gridWrittenAt = Number.NEGATIVE_INFINITY;
  let looks = 0;
  let skipped = 0;
  let pending = 0;

  function learnHeights(look: PerceivedLook): void {
    for (const object of look.remembered) {
      let best: PerceivedSighting | undefined;
      let bestM = SAME_OBJECT_M;
      for (const seen of look.objects) {
        if (seen.colour !== object.colour) continue;
        const m = Math.hypot(seen.world.x - object.x, seen.world.y - object.y);
        if (m < bestM) [best, bestM] = [seen, m];
      }
      if (best !== undefined) heights.set(object.id, best.heightM);
    }
  }

  function write(look: PerceivedLook, objects: PerceivedObject[], at: bigint): void {
    learnHeights(look);
    recorder.write(topics.detections, sightingsScene(look.objects, at), at);
    recorder.write(topics.objects, objectsScene(objects, heights, at), at);
    if (grid === undefined || grid.version === gridVersion) return;
    const now = performance.now();
    if (now - gridWrittenAt < gridPeriodMs) return;
    gridVersion = grid.version;
    gridWrittenAt = now;
    recorder.write(topics.grid, gridMessage(grid, at), at);
  }

  const unsubscribe = perception.onLook((look) => {
    looks += 1;
    if (pending >= MAX_PENDING_LOOKS) {
      skipped += 1;
      return;
    }
    // what the look handed over and the memory as it is now; the messages are made later
    const at = recorder.clock();
    let objects: PerceivedObject[];
    try {
      objects = perception.memory.all();
    } catch {
      return;
    }
    pending += 1;
    recorder.defer(() => {
      pending -= 1;
      write(look, objects, at);
    });
  });
  return {
    get looks() {
      return looks;
    },
    get skipped() {
      return skipped;
    },
    stop: unsubscribe,
  };
}
