import jpeg from 'jpeg-js';
import { worldToCell } from './geometry.js';
import type { Point, Pose2D } from './geometry.js';
import type { OccupancyGrid } from './occupancy-grid.js';

/** An RGBA image, row 0 at the top. */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array;
}

/** What to draw over the grid. */
export interface GridImageOptions {
  pose?: Pose2D;
  goal?: Point | null;
  path?: readonly Point[];
  /** The image's longer side, pixels (the grid is scaled by a whole factor to about this). Default 200. */
  size?: number;
  /** Shade the cells the robot's centre may not enter (obstacles inflated). Default true. */
  showInflation?: boolean;
}

type Rgb = readonly [number, number, number];
const COLOURS = {
  unknown: [150, 150, 150],
  free: [250, 250, 250],
  occupied: [20, 20, 20],
  inflated: [235, 200, 200],
  path: [30, 90, 230],
  robot: [20, 160, 60],
  goal: [220, 40, 40],
} as const satisfies Record<string, Rgb>;

/**
 * Draws the grid as an RGBA picture, north (+y) up: unknown grey, free white, occupied black,
 * cells too near an obstacle for the robot's centre pink, the planned route blue, the robot a
 * green disc with a heading tick, the goal a red cross. Pure: works in browsers and Node.
 */
export function renderGridImage(grid: OccupancyGrid, options: GridImageOptions = {}): RgbaImage {
  const { spec } = grid;
  const scale = Math.max(1, Math.floor((options.size ?? 200) / Math.max(spec.width, spec.height)));
  const width = spec.width * scale;
  const height = spec.height * scale;
  const data = new Uint8Array(width * height * 4);
  const set = (px: number, py: number, c: Rgb) => {
    if (px < 0 || py < 0 || px >= width || py >= height) return;
    const o = (py * width + px) * 4;
    data[o] = c[0];
    data[o + 1] = c[1];
    data[o + 2] = c[2];
    data[o + 3] = 255;
  };
  const inflation = options.showInflation !== false;
  for (let cy = 0; cy < spec.height; cy += 1) {
    for (let cx = 0; cx < spec.width; cx += 1) {
      const state = grid.stateOf(cx, cy);
      const colour =
        state === 'occupied'
          ? COLOURS.occupied
          : inflation && grid.obstacles.isBlocked(cx, cy)
            ? COLOURS.inflated
            : COLOURS[state];
      const top = (spec.height - 1 - cy) * scale;
      for (let dy = 0; dy < scale; dy += 1) {
        for (let dx = 0; dx < scale; dx += 1) set(cx * scale + dx, top + dy, colour);
      }
    }
  }
  // World point -> pixel (sub-cell precision).
  const toPixel = (p: Point): [number, number] => [
    ((p.x - spec.originX) / spec.resolutionM) * scale,
    height - ((p.y - spec.originY) / spec.resolutionM) * scale,
  ];
  const line = (a: Point, b: Point, c: Rgb) => {
    const [ax, ay] = toPixel(a);
    const [bx, by] = toPixel(b);
    const steps = Math.ceil(Math.max(Math.abs(bx - ax), Math.abs(by - ay))) + 1;
    for (let s = 0; s <= steps; s += 1) {
      const t = s / steps;
      set(Math.floor(ax + t * (bx - ax)), Math.floor(ay + t * (by - ay)), c);
    }
  };
  const path = options.path ?? [];
  for (let k = 1; k < path.length; k += 1)
    line(path[k - 1] as Point, path[k] as Point, COLOURS.path);
  const goal = options.goal;
  if (goal !== undefined && goal !== null && worldToCell(spec, goal.x, goal.y) !== undefined) {
    const arm = (Math.max(3, scale * 2) * spec.resolutionM) / scale;
    line({ x: goal.x - arm, y: goal.y - arm }, { x: goal.x + arm, y: goal.y + arm }, COLOURS.goal);
    line({ x: goal.x - arm, y: goal.y + arm }, { x: goal.x + arm, y: goal.y - arm }, COLOURS.goal);
  }
  const pose = options.pose;
  if (pose !== undefined) {
    const [px, py] = toPixel(pose);
    const r = Math.max(2, (grid.robotRadiusM / spec.resolutionM) * scale);
    for (let dy = -Math.ceil(r); dy <= Math.ceil(r); dy += 1) {
      for (let dx = -Math.ceil(r); dx <= Math.ceil(r); dx += 1) {
        if (dx * dx + dy * dy <= r * r)
          set(Math.floor(px + dx), Math.floor(py + dy), COLOURS.robot);
      }
    }
    const reach = (2 * r * spec.resolutionM) / scale;
    line(
      pose,
      { x: pose.x + reach * Math.cos(pose.yaw), y: pose.y + reach * Math.sin(pose.yaw) },
      COLOURS.occupied,
    );
  }
  return { width, height, data };
}

function toBase64(bytes: Uint8Array): string {
  const buffer = (
    globalThis as { Buffer?: { from(b: Uint8Array): { toString(e: string): string } } }
  ).Buffer;
  if (buffer !== undefined) return buffer.from(bytes).toString('base64');
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) {
    binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  }
  return btoa(binary);
}

/**
 * The grid as a JPEG data URL (`data:image/jpeg;base64,...`) for an LLM prompt, via jpeg-js.
 * Node only (jpeg-js needs `Buffer`); in a browser draw {@link renderGridImage} on a canvas.
 */
export function gridImageDataUrl(
  grid: OccupancyGrid,
  options: GridImageOptions & { quality?: number } = {},
): string {
  const image = renderGridImage(grid, options);
  const encoded = jpeg.encode(image, options.quality ?? 85);
  return `data:image/jpeg;base64,${toBase64(new Uint8Array(encoded.data))}`;
}
