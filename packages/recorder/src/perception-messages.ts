/*
 * What perception believes, as Foxglove messages: the remembered objects and one frame's
 * sightings as foxglove.SceneUpdate (a cube for a box, a cylinder for a pillar or anything else,
 * in its colour, where it is, its label beside it), the occupancy grid as foxglove.Grid. The
 * shapes perception hands over are described here structurally, so the recorder does not depend
 * on @hal/perception.
 */
import { foxgloveTime } from './foxglove-schemas.js';
import { NUMERIC_TYPE } from './foxglove-scene-schemas.js';

/** An object perception remembers (a `RememberedObject` of @hal/perception). World frame, metres. */
export interface PerceivedObject {
  id: string;
  colour: string;
  kind: string;
  label: string;
  x: number;
  y: number;
  uncertaintyM: number;
  widthM: number;
  timesSeen: number;
  lastSeenAt: number;
}

/** One object seen in one frame (a `SeenObject` of @hal/perception). */
export interface PerceivedSighting {
  colour: string;
  kind: string;
  label: string;
  bearingDeg: number;
  distanceM: number;
  widthM: number;
  heightM: number;
  confidence: number;
  world: { x: number; y: number };
  detector: string;
}

/** An occupancy grid (`@hal/navigation`'s `OccupancyGrid`): cells `cy * width + cx`, row 0 at the origin. */
export interface PerceivedGrid {
  readonly spec: {
    readonly width: number;
    readonly height: number;
    readonly resolutionM: number;
    readonly originX: number;
    readonly originY: number;
  };
  /** Changes whenever a cell's state changes. */
  readonly version: number;
  stateOf(cx: number, cy: number): 'unknown' | 'free' | 'occupied';
}

/** The frame perception's world positions are in: the recorded pose's frame (odometry). */
export const PERCEPTION_FRAME = 'world';

/** The occupancy byte of each cell state (ROS's OccupancyGrid values; unknown is -1 as a byte). */
export const OCCUPANCY = Object.freeze({ free: 0, occupied: 100, unknown: 255 });

/** The simulator's object colours (RGB 0..1) by palette name; grey for any other. */
const COLOURS: Readonly<Record<string, readonly [number, number, number]>> = {
  red: [0.839, 0.157, 0.157],
  orange: [0.969, 0.498, 0],
  yellow: [0.957, 0.769, 0.188],
  green: [0.165, 0.616, 0.247],
  blue: [0.114, 0.306, 0.847],
  purple: [0.482, 0.173, 0.749],
};

function colorOf(name: string, a: number): { r: number; g: number; b: number; a: number } {
  const [r, g, b] = COLOURS[name] ?? [0.5, 0.5, 0.5];
  return { r, g, b, a };
}

const LEVEL = { x: 0, y: 0, z: 0, w: 1 } as const;
const FOREVER = { sec: 0, nsec: 0 } as const;

interface Shape {
  id: string;
  colour: string;
  kind: string;
  label: string;
  x: number;
  y: number;
  widthM: number;
  heightM: number;
  metadata: Record<string, string>;
}

function entity(shape: Shape, timestamp: { sec: number; nsec: number }, alpha: number) {
  const { x, y, widthM, heightM } = shape;
  const size = { x: widthM, y: widthM, z: heightM };
  const pose = { position: { x, y, z: heightM / 2 }, orientation: LEVEL };
  const color = colorOf(shape.colour, alpha);
  const box = shape.kind === 'box';
  return {
    timestamp,
    frame_id: PERCEPTION_FRAME,
    id: shape.id,
    lifetime: FOREVER,
    frame_locked: false,
    metadata: Object.entries(shape.metadata).map(([key, value]) => ({ key, value })),
    arrows: [],
    cubes: box ? [{ pose, size, color }] : [],
    spheres: [],
    cylinders: box ? [] : [{ pose, size, bottom_scale: 1, top_scale: 1, color }],
    lines: [],
    triangles: [],
    texts: [
      {
        pose: { position: { x, y, z: heightM + 0.05 }, orientation: LEVEL },
        billboard: true,
        font_size: 14,
        scale_invariant: true,
        color: colorOf(shape.colour, 1),
        text: shape.id,
      },
    ],
    models: [],
  };
}

/** A scene update that replaces everything shown before (deletions apply before the entities). */
function replaceAll(timestamp: { sec: number; nsec: number }, entities: unknown[]) {
  return { deletions: [{ timestamp, type: 1, id: '' }], entities };
}

const fixed = (value: number, digits = 3) => value.toFixed(digits);

/**
 * The remembered objects as a scene update at `at` (ns): one entity each (id its name, e.g.
 * "red box 1"), `heights` giving the height last seen of each (default its width).
 */
export function objectsScene(
  objects: readonly PerceivedObject[],
  heights: ReadonlyMap<string, number>,
  at: bigint,
) {
  const timestamp = foxgloveTime(at);
  return replaceAll(
    timestamp,
    objects.map((o) =>
      entity(
        {
          ...o,
          heightM: heights.get(o.id) ?? o.widthM,
          metadata: {
            label: o.label,
            kind: o.kind,
            colour: o.colour,
            uncertainty_m: fixed(o.uncertaintyM),
            times_seen: String(o.timesSeen),
            last_seen_at: new Date(o.lastSeenAt).toISOString(),
          },
        },
        timestamp,
        // surer the more often it was seen
        Math.min(0.9, 0.4 + 0.1 * o.timesSeen),
      ),
    ),
  );
}

/** One frame's sightings as a scene update at `at` (ns): entity ids `sighting 1`, `sighting 2`, ... */
export function sightingsScene(sightings: readonly PerceivedSighting[], at: bigint) {
  const timestamp = foxgloveTime(at);
  return replaceAll(
    timestamp,
    sightings.map((s, i) =>
      entity(
        {
          id: `sighting ${i + 1}`,
          colour: s.colour,
          kind: s.kind,
          label: s.label,
          x: s.world.x,
          y: s.world.y,
          widthM: s.widthM,
          heightM: s.heightM,
          metadata: {
            label: s.label,
            bearing_deg: fixed(s.bearingDeg, 1),
            distance_m: fixed(s.distanceM),
            confidence: fixed(s.confidence, 2),
            detector: s.detector,
          },
        },
        timestamp,
        0.5,
      ),
    ),
  );
}

/** `bytes` in base64: Node's Buffer where there is one, else the browser's btoa. */
function base64(bytes: Uint8Array): string {
  if (typeof Buffer === 'function') {
    return Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength).toString('base64');
  }
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) {
    text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  }
  return btoa(text);
}

/** The grid as a foxglove.Grid at `at` (ns): one uint8 field `occupancy` ({@link OCCUPANCY}). */
export function gridMessage(grid: PerceivedGrid, at: bigint) {
  const { width, height, resolutionM, originX, originY } = grid.spec;
  const cells = new Uint8Array(width * height);
  for (let cy = 0; cy < height; cy += 1) {
    for (let cx = 0; cx < width; cx += 1) {
      cells[cy * width + cx] = OCCUPANCY[grid.stateOf(cx, cy)];
    }
  }
  return {
    timestamp: foxgloveTime(at),
    frame_id: PERCEPTION_FRAME,
    pose: { position: { x: originX, y: originY, z: 0 }, orientation: LEVEL },
    column_count: width,
    cell_size: { x: resolutionM, y: resolutionM },
    row_stride: width,
    cell_stride: 1,
    fields: [{ name: 'occupancy', offset: 0, type: NUMERIC_TYPE.UINT8 }],
    data: base64(cells),
  };
}
