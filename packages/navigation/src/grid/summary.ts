import { cellCentre, gridExtent, worldToCell } from './geometry.js';
import type { Point, Pose2D } from './geometry.js';
import type { OccupancyGrid } from './occupancy-grid.js';
import type { RangeReadings } from './range-sensor-update.js';

/** What to put in a world summary besides the grid itself. */
export interface WorldSummaryOptions {
  pose?: Pose2D;
  goal?: Point | null;
  /** The planned route, metres (drawn on the coarse map as `*`). */
  path?: readonly Point[];
  /** The latest range readings, metres. */
  readings?: RangeReadings;
  /** Cells of the coarse character map along its longer side. Default 25. */
  mapChars?: number;
}

const RAD = 180 / Math.PI;

const fmt = (v: number, digits = 2) => (Object.is(v, -0) ? 0 : v).toFixed(digits);

/**
 * A compact text summary of the world model for an LLM prompt: the grid's extent and how much is
 * known, the robot's pose, the goal's distance and bearing, the latest range readings, and a
 * coarse character map (north, +y, up; `#` occupied, `.` free, `?` unknown, `R` robot, `G` goal,
 * `*` planned route). A coarse cell shows `#` when any fine cell in it is occupied.
 */
export function describeWorld(grid: OccupancyGrid, options: WorldSummaryOptions = {}): string {
  const { spec } = grid;
  const counts = grid.counts();
  const total = spec.width * spec.height;
  const pct = (n: number) => `${Math.round((100 * n) / total)}%`;
  const lines: string[] = [];
  const { minX: x0, minY: y0, maxX: x1, maxY: y1 } = gridExtent(spec);
  lines.push(
    `World: x ${fmt(x0)}..${fmt(x1)} m, y ${fmt(y0)}..${fmt(y1)} m, cells ${Math.round(
      spec.resolutionM * 100,
    )} cm; free ${pct(counts.free)}, occupied ${pct(counts.occupied)}, unknown ${pct(counts.unknown)}.`,
  );
  lines.push('Frame: x forward/east, y left/north, yaw counter-clockwise from +x, degrees.');
  const { pose, goal } = options;
  if (pose !== undefined) {
    lines.push(
      `Robot: at (${fmt(pose.x)}, ${fmt(pose.y)}) m, heading ${fmt(pose.yaw * RAD, 0)} deg.`,
    );
  }
  if (goal !== undefined && goal !== null) {
    let text = `Goal: (${fmt(goal.x)}, ${fmt(goal.y)}) m`;
    if (pose !== undefined) {
      const dx = goal.x - pose.x;
      const dy = goal.y - pose.y;
      const bearing = Math.atan2(dy, dx);
      let relative = (bearing - pose.yaw) * RAD;
      relative = ((((relative + 180) % 360) + 360) % 360) - 180;
      text += `, ${fmt(Math.hypot(dx, dy))} m away, bearing ${fmt(bearing * RAD, 0)} deg (${fmt(
        Math.abs(relative),
        0,
      )} deg to the ${relative >= 0 ? 'left' : 'right'})`;
    }
    lines.push(`${text}.`);
  }
  if (options.readings !== undefined) {
    const r = options.readings;
    lines.push(
      `Range sensors: front ${fmt(r.front)} m, left ${fmt(r.left)} m, right ${fmt(r.right)} m.`,
    );
  }
  if (options.path !== undefined && options.path.length > 0) {
    lines.push(
      `Planned route: ${options.path.map((p) => `(${fmt(p.x)}, ${fmt(p.y)})`).join(' -> ')}.`,
    );
  }

  // The coarse map.
  const chars = Math.max(4, Math.floor(options.mapChars ?? 25));
  const block = Math.max(1, Math.ceil(Math.max(spec.width, spec.height) / chars));
  const cols = Math.ceil(spec.width / block);
  const rows = Math.ceil(spec.height / block);
  const picture: string[][] = [];
  for (let r = 0; r < rows; r += 1) {
    const row: string[] = [];
    for (let c = 0; c < cols; c += 1) {
      let occupied = false;
      let free = 0;
      let cells = 0;
      for (let cy = r * block; cy < Math.min(spec.height, (r + 1) * block); cy += 1) {
        for (let cx = c * block; cx < Math.min(spec.width, (c + 1) * block); cx += 1) {
          const state = grid.stateOf(cx, cy);
          cells += 1;
          if (state === 'occupied') occupied = true;
          else if (state === 'free') free += 1;
        }
      }
      row.push(occupied ? '#' : free * 2 >= cells ? '.' : '?');
    }
    picture.push(row);
  }
  const put = (p: Point, ch: string) => {
    const cell = worldToCell(spec, p.x, p.y);
    if (cell === undefined) return;
    const row = picture[Math.floor(cell.cy / block)];
    if (row !== undefined) row[Math.floor(cell.cx / block)] = ch;
  };
  if (options.path !== undefined) {
    for (let k = 1; k < options.path.length; k += 1) {
      const a = options.path[k - 1] as Point;
      const b = options.path[k] as Point;
      const steps = Math.ceil(Math.hypot(b.x - a.x, b.y - a.y) / (spec.resolutionM * block)) * 2;
      for (let s = 0; s <= steps; s += 1) {
        const t = steps === 0 ? 0 : s / steps;
        put({ x: a.x + t * (b.x - a.x), y: a.y + t * (b.y - a.y) }, '*');
      }
    }
  }
  if (goal !== undefined && goal !== null) put(goal, 'G');
  if (pose !== undefined) put(pose, 'R');
  const blockM = block * spec.resolutionM;
  lines.push(
    `Map (${cols}x${rows}, ${fmt(blockM * 100, 0)} cm per character, north up; # occupied, . free, ? unknown, R robot, G goal, * route):`,
  );
  for (let r = rows - 1; r >= 0; r -= 1) lines.push((picture[r] as string[]).join(''));
  const corner = cellCentre(spec, 0, 0);
  lines.push(`(bottom-left character is at about (${fmt(corner.x)}, ${fmt(corner.y)}) m)`);
  return lines.join('\n');
}
