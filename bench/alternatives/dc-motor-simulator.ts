// The alternative the simulation benchmark runs against: the robot simulator of the TypeScript
// robot stack this project replaces, modelled here from its published behaviour (not its code).
// It has no stepper model: each robot is a pair of DC motors whose wheel speed is proportional to
// PWM, integrated with a fixed 10 ms Euler step. On every step it does what that simulator does:
// wheel speeds from PWM, pose update, a collision test against the walls (segments) and round
// obstacles, a clamp to the arena, encoder ticks, battery drain, checkpoints, and the state
// snapshot it hands to its listener (eight ray-cast range readings with noise, five line sensors,
// an IMU with noise). One simulator object per robot; robots do not see each other.

export interface Segment {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
}
export interface Disc {
  x: number;
  y: number;
  radius: number;
}
export interface DcArena {
  bounds: { minX: number; maxX: number; minY: number; maxY: number };
  walls: Segment[];
  obstacles: Disc[];
  lines: Array<{ points: Array<{ x: number; y: number }>; width: number }>;
  checkpoints: Array<{ x: number; y: number }>;
}

const BODY = 0.08;
const WHEEL_RADIUS = 0.0325;
const WHEEL_BASE = 0.07;
const MAX_RPM = 300;
const RANGE = 2;
const RAY_ANGLES = [
  0,
  -Math.PI / 4,
  Math.PI / 4,
  -Math.PI / 2,
  Math.PI / 2,
  Math.PI,
  (-3 * Math.PI) / 4,
  (3 * Math.PI) / 4,
];

function wrap(a: number): number {
  while (a > Math.PI) a -= 2 * Math.PI;
  while (a < -Math.PI) a += 2 * Math.PI;
  return a;
}

function segmentDistance(px: number, py: number, s: Segment): number {
  const dx = s.x2 - s.x1;
  const dy = s.y2 - s.y1;
  const len2 = dx * dx + dy * dy;
  let t = len2 === 0 ? 0 : ((px - s.x1) * dx + (py - s.y1) * dy) / len2;
  t = Math.max(0, Math.min(1, t));
  return Math.hypot(px - (s.x1 + t * dx), py - (s.y1 + t * dy));
}

function raySegment(x: number, y: number, angle: number, s: Segment): number | undefined {
  const ex = x + Math.cos(angle) * 10;
  const ey = y + Math.sin(angle) * 10;
  const denom = (s.x1 - s.x2) * (y - ey) - (s.y1 - s.y2) * (x - ex);
  if (Math.abs(denom) < 1e-4) return undefined;
  const t = ((s.x1 - x) * (y - ey) - (s.y1 - y) * (x - ex)) / denom;
  const u = -((s.x1 - s.x2) * (s.y1 - y) - (s.y1 - s.y2) * (s.x1 - x)) / denom;
  if (t < 0 || t > 1 || u < 0) return undefined;
  return Math.hypot(s.x1 + t * (s.x2 - s.x1) - x, s.y1 + t * (s.y2 - s.y1) - y);
}

function rayDisc(x: number, y: number, angle: number, d: Disc): number | undefined {
  const dx = Math.cos(angle);
  const dy = Math.sin(angle);
  const fx = x - d.x;
  const fy = y - d.y;
  const b = 2 * (fx * dx + fy * dy);
  const c = fx * fx + fy * fy - d.radius * d.radius;
  const disc = b * b - 4 * c;
  if (disc < 0) return undefined;
  const t1 = (-b - Math.sqrt(disc)) / 2;
  const t2 = (-b + Math.sqrt(disc)) / 2;
  return t1 >= 0 ? t1 : t2 >= 0 ? t2 : undefined;
}

export class DcMotorSimulator {
  readonly pose: { x: number; y: number; rotation: number };
  readonly #arena: DcArena;
  readonly #onState: (state: unknown) => void;
  #leftPwm = 0;
  #rightPwm = 0;
  #linear = 0;
  #angular = 0;
  #encoders = { left: 0, right: 0 };
  #battery = 1000;
  #bumper = { front: false, back: false };
  readonly #reached = new Set<number>();
  /** Whether each step builds the state snapshot for the listener (the stack always does). */
  snapshots = true;

  constructor(
    arena: DcArena,
    start: { x: number; y: number; rotation: number },
    onState: (state: unknown) => void,
  ) {
    this.#arena = arena;
    this.pose = { ...start };
    this.#onState = onState;
  }

  drive(leftPwm: number, rightPwm: number): void {
    this.#leftPwm = Math.max(-255, Math.min(255, leftPwm));
    this.#rightPwm = Math.max(-255, Math.min(255, rightPwm));
  }

  /** One physics step of `dt` seconds (the stack runs it every 10 ms). */
  step(dt: number): void {
    const vmax = (MAX_RPM / 60) * 2 * Math.PI * WHEEL_RADIUS;
    const vl = (this.#leftPwm / 255) * vmax;
    const vr = (this.#rightPwm / 255) * vmax;
    this.#linear = (vl + vr) / 2;
    this.#angular = (vr - vl) / WHEEL_BASE;
    const p = this.pose;
    const rotation = wrap(p.rotation + this.#angular * dt);
    const nx = p.x + this.#linear * Math.cos(p.rotation) * dt;
    const ny = p.y + this.#linear * Math.sin(p.rotation) * dt;
    this.#bumper = this.#collision(nx, ny);
    if (!this.#bumper.front && !this.#bumper.back) {
      p.x = nx;
      p.y = ny;
      p.rotation = rotation;
    }
    const b = this.#arena.bounds;
    p.x = Math.max(b.minX + BODY / 2, Math.min(b.maxX - BODY / 2, p.x));
    p.y = Math.max(b.minY + BODY / 2, Math.min(b.maxY - BODY / 2, p.y));
    this.#encoders.left += Math.round(vl * dt * 1000);
    this.#encoders.right += Math.round(vr * dt * 1000);
    const load = (Math.abs(this.#leftPwm) + Math.abs(this.#rightPwm)) / 510;
    this.#battery = Math.max(0, this.#battery - ((50 + load * 500 + 20) * dt) / 3600);
    this.#arena.checkpoints.forEach((c, i) => {
      if (!this.#reached.has(i) && Math.hypot(p.x - c.x, p.y - c.y) < 0.1) this.#reached.add(i);
    });
    if (this.snapshots) this.#onState(this.#snapshot());
  }

  #collision(x: number, y: number): { front: boolean; back: boolean } {
    let front = false;
    let back = false;
    for (const w of this.#arena.walls) {
      if (segmentDistance(x, y, w) < BODY / 2) {
        const facing = Math.abs(wrap(this.pose.rotation - Math.atan2(w.y2 - w.y1, w.x2 - w.x1)));
        if (facing < Math.PI / 2) front = true;
        else back = true;
      }
    }
    for (const o of this.#arena.obstacles) {
      if (Math.hypot(x - o.x, y - o.y) < BODY / 2 + o.radius) {
        const facing = Math.abs(wrap(this.pose.rotation - Math.atan2(o.y - y, o.x - x)));
        if (facing < Math.PI / 2) front = true;
        else back = true;
      }
    }
    return { front, back };
  }

  #snapshot(): unknown {
    const p = this.pose;
    const ranges: Record<string, number> = {};
    RAY_ANGLES.forEach((offset, i) => {
      let best = RANGE;
      for (const w of this.#arena.walls)
        best = Math.min(best, raySegment(p.x, p.y, p.rotation + offset, w) ?? best);
      for (const o of this.#arena.obstacles)
        best = Math.min(best, rayDisc(p.x, p.y, p.rotation + offset, o) ?? best);
      best += (Math.random() - 0.5) * 0.01;
      ranges[`ray${i}`] = Math.round(Math.max(0, Math.min(RANGE, best)) * 100);
    });
    const line: number[] = [];
    for (let i = 0; i < 5; i += 1) {
      const lx = 0.04;
      const ly = (i - 2) * 0.015;
      const wx = p.x + lx * Math.cos(p.rotation) - ly * Math.sin(p.rotation);
      const wy = p.y + lx * Math.sin(p.rotation) + ly * Math.cos(p.rotation);
      const on = this.#arena.lines.some((l) =>
        l.points.some((a, j) => {
          const b = l.points[j + 1];
          return (
            b !== undefined &&
            segmentDistance(wx, wy, { x1: a.x, y1: a.y, x2: b.x, y2: b.y }) < l.width / 2
          );
        }),
      );
      line.push(on ? 255 : 0);
    }
    const noise = () => (Math.random() - 0.5) * 0.1;
    return {
      pose: { ...p },
      velocity: { linear: this.#linear, angular: this.#angular },
      sensors: {
        distance: ranges,
        line,
        imu: {
          accel: {
            x: this.#linear * Math.cos(p.rotation) + noise(),
            y: this.#linear * Math.sin(p.rotation) + noise(),
            z: 9.81 + noise(),
          },
          gyro: { x: noise() / 2, y: noise() / 2, z: this.#angular + noise() / 2 },
          heading: (p.rotation * 180) / Math.PI,
        },
        bumper: { ...this.#bumper },
        encoders: { ...this.#encoders },
      },
      battery: {
        voltage: 3 + (this.#battery / 1000) * 1.2,
        percentage: Math.round(this.#battery / 10),
      },
    };
  }
}

/** A walled arena of `width` x `height` metres centred on the origin, as that stack describes one. */
export function dcArena(width: number, height: number): DcArena {
  const x = width / 2;
  const y = height / 2;
  return {
    bounds: { minX: -x, maxX: x, minY: -y, maxY: y },
    walls: [
      { x1: -x, y1: -y, x2: x, y2: -y },
      { x1: x, y1: -y, x2: x, y2: y },
      { x1: x, y1: y, x2: -x, y2: y },
      { x1: -x, y1: y, x2: -x, y2: -y },
    ],
    obstacles: [],
    lines: [],
    checkpoints: [],
  };
}
