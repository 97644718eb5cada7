// The simulator's truth about what the camera sees, for the perception benchmarks: which coloured
// solids are in view from a pose (their footprint inside the image, how much of them is hidden
// behind other solids), and which grid cells the world's solids cover. Computed from the world's
// plan and the one camera model, independently of the image the renderer draws.
import { pixelOfPoint } from '@hal/kinematics';
import type { CameraProjection } from '@hal/kinematics';
import { colourOf } from '@hal/perception';
import type { ColourName } from '@hal/perception';
import { castRay } from '@hal/simulation';
import type { Solid } from '@hal/simulation';

/** A pose in the world, metres and radians. */
export interface PlanePose {
  x: number;
  y: number;
  yaw: number;
}

/** A solid whose colour the palette names: an object perception should find. */
export interface ColouredSolid {
  solid: Solid;
  colour: ColourName;
  /** Box or pillar, as perception names them. */
  kind: 'box' | 'pillar';
  centre: { x: number; y: number };
}

/** How one coloured solid appears from one pose. */
export interface SolidView {
  object: ColouredSolid;
  /** Ground distance from the robot's centre to the solid's centre, metres. */
  distanceM: number;
  /** Whether every point of its footprint projects inside the image (its top may be cut). */
  inView: boolean;
  /** Fewest pixels between its footprint's projection and the image's left or right edge. */
  sideMarginPx: number;
  /** Share of its camera-facing sample points that no other solid hides, 0..1. */
  visible: number;
}

/**
 * The solids that count as objects: those whose true colour the palette names (`colourOf` of
 * the solid's colour). This includes map furniture drawn in a palette colour.
 */
export function colouredSolids(solids: readonly Solid[]): ColouredSolid[] {
  const out: ColouredSolid[] = [];
  for (const solid of solids) {
    const colour = colourOf(solid.color.r, solid.color.g, solid.color.b);
    if (colour === undefined) continue;
    out.push({
      solid,
      colour,
      kind: solid.kind === 'box' ? 'box' : 'pillar',
      centre:
        solid.kind === 'box'
          ? { x: (solid.minX + solid.maxX) / 2, y: (solid.minY + solid.maxY) / 2 }
          : { x: solid.x, y: solid.y },
    });
  }
  return out;
}

/** Points around a solid's footprint, world frame (corners and edge points; a circle of 24). */
function footprint(solid: Solid): Array<{ x: number; y: number }> {
  if (solid.kind === 'cylinder') {
    return Array.from({ length: 24 }, (_, i) => ({
      x: solid.x + solid.radius * Math.cos((i * Math.PI) / 12),
      y: solid.y + solid.radius * Math.sin((i * Math.PI) / 12),
    }));
  }
  const points: Array<{ x: number; y: number }> = [];
  const steps = 6;
  for (let i = 0; i < steps; i += 1) {
    const f = i / steps;
    const x = solid.minX + f * (solid.maxX - solid.minX);
    const y = solid.minY + f * (solid.maxY - solid.minY);
    points.push(
      { x, y: solid.minY },
      { x: solid.maxX, y },
      { x: solid.maxX + solid.minX - x, y: solid.maxY },
      { x: solid.minX, y: solid.maxY + solid.minY - y },
    );
  }
  return points;
}

/** A world point in the robot's frame at `pose`. */
export function toRobot(pose: PlanePose, x: number, y: number): { x: number; y: number } {
  const dx = x - pose.x;
  const dy = y - pose.y;
  const c = Math.cos(pose.yaw);
  const s = Math.sin(pose.yaw);
  return { x: c * dx + s * dy, y: -s * dx + c * dy };
}

/** Distance along the plan ray from (ox, oy) at `angle` at which it enters `solid` (or Infinity). */
function enter(ox: number, oy: number, angle: number, solid: Solid): number {
  const { distance, solid: hit } = castRay(ox, oy, angle, Number.POSITIVE_INFINITY, [solid]);
  return hit === undefined ? Number.POSITIVE_INFINITY : distance;
}

/**
 * Whether the straight line from the lens to (px, py, pz) passes through `other`: it crosses
 * the solid's plan and is at or below the solid's height where it enters or where it leaves.
 */
function blocks(
  lens: { x: number; y: number; z: number },
  px: number,
  py: number,
  pz: number,
  other: Solid,
): boolean {
  const d = Math.hypot(px - lens.x, py - lens.y);
  const angle = Math.atan2(py - lens.y, px - lens.x);
  const tIn = enter(lens.x, lens.y, angle, other);
  if (!(tIn < d)) return false;
  const tOut = d - enter(px, py, angle + Math.PI, other);
  const zAt = (t: number) => lens.z + ((pz - lens.z) * t) / d;
  return zAt(tIn) <= other.height || zAt(Math.max(tIn, tOut)) <= other.height;
}

/** How `object` appears from `pose` through `projection`, among `solids` (its own included). */
export function viewOf(
  object: ColouredSolid,
  pose: PlanePose,
  projection: CameraProjection,
  solids: readonly Solid[],
): SolidView {
  const { camera } = projection;
  const c = Math.cos(pose.yaw);
  const s = Math.sin(pose.yaw);
  const lens = {
    x: pose.x + camera.forwardM * c - camera.leftM * s,
    y: pose.y + camera.forwardM * s + camera.leftM * c,
    z: camera.heightM,
  };
  const points = footprint(object.solid);
  let inView = true;
  let sideMarginPx = Number.POSITIVE_INFINITY;
  for (const p of points) {
    const r = toRobot(pose, p.x, p.y);
    const pixel = pixelOfPoint(projection, { x: r.x, y: r.y, z: 0 });
    if (
      pixel === undefined ||
      pixel.u < 0 ||
      pixel.u > camera.width ||
      pixel.v < 0 ||
      pixel.v > camera.height
    ) {
      inView = false;
      sideMarginPx = 0;
      break;
    }
    sideMarginPx = Math.min(sideMarginPx, pixel.u, camera.width - pixel.u);
  }
  // Camera-facing sample points (the solid's own plan does not hide them) at three heights.
  const others = solids.filter((o) => o !== object.solid);
  const h = object.solid.height;
  let facing = 0;
  let seen = 0;
  for (const p of points) {
    const d = Math.hypot(p.x - lens.x, p.y - lens.y);
    const own = enter(lens.x, lens.y, Math.atan2(p.y - lens.y, p.x - lens.x), object.solid);
    if (own < d - 1e-3) continue; // on its far side
    for (const z of [0.02, h / 2, h - 0.02]) {
      facing += 1;
      if (!others.some((o) => blocks(lens, p.x, p.y, z, o))) seen += 1;
    }
  }
  const centre = toRobot(pose, object.centre.x, object.centre.y);
  return {
    object,
    distanceM: Math.hypot(centre.x, centre.y),
    inView,
    sideMarginPx,
    visible: facing === 0 ? 0 : seen / facing,
  };
}

/** Distance from (x, y) to the nearest point of `solid`'s plan, metres (0 inside it). */
export function distanceToSolid(x: number, y: number, solid: Solid): number {
  if (solid.kind === 'box') {
    const dx = x < solid.minX ? solid.minX - x : x > solid.maxX ? x - solid.maxX : 0;
    const dy = y < solid.minY ? solid.minY - y : y > solid.maxY ? y - solid.maxY : 0;
    return Math.hypot(dx, dy);
  }
  return Math.max(0, Math.hypot(x - solid.x, y - solid.y) - solid.radius);
}

/** Whether any solid covers (x, y), or comes within `toleranceM` of it. */
export function covered(x: number, y: number, solids: readonly Solid[], toleranceM = 0): boolean {
  return solids.some((solid) => distanceToSolid(x, y, solid) <= toleranceM);
}
