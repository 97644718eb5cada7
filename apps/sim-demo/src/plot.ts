import type { World } from '@hal/simulation';

/** A top view of the arena: solids, the robot's trail, the goal and the robot, on a 2D canvas. */
export class TrajectoryPlot {
  readonly #canvas: HTMLCanvasElement;
  readonly #ctx: CanvasRenderingContext2D;
  #trail: Array<{ x: number; y: number }> = [];

  constructor(canvas: HTMLCanvasElement) {
    this.#canvas = canvas;
    const ctx = canvas.getContext('2d');
    if (ctx === null) throw new Error('no 2D canvas');
    this.#ctx = ctx;
  }

  clear(): void {
    this.#trail = [];
  }

  /** Records the robot's position when it has moved at least 5 mm. */
  record(x: number, y: number): void {
    const last = this.#trail[this.#trail.length - 1];
    if (last === undefined || Math.hypot(x - last.x, y - last.y) > 0.005) {
      this.#trail.push({ x, y });
      if (this.#trail.length > 20_000) this.#trail.splice(0, 1000);
    }
  }

  get trail(): ReadonlyArray<{ x: number; y: number }> {
    return this.#trail;
  }

  draw(world: World, robotId: string, goal: { x: number; y: number } | undefined): void {
    const ctx = this.#ctx;
    const { width: w, height: h } = this.#canvas;
    const { arena } = world.map;
    const pad = 12;
    const scale = Math.min((w - 2 * pad) / arena.width, (h - 2 * pad) / arena.height);
    const px = (x: number) => w / 2 + x * scale;
    const py = (y: number) => h / 2 - y * scale;
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = '#f7f4ec';
    ctx.fillRect(
      px(-arena.width / 2),
      py(arena.height / 2),
      arena.width * scale,
      arena.height * scale,
    );
    ctx.strokeStyle = '#e4ddcd';
    ctx.lineWidth = 1;
    for (let x = -arena.width / 2; x <= arena.width / 2 + 1e-9; x += 0.5) {
      ctx.beginPath();
      ctx.moveTo(px(x), py(-arena.height / 2));
      ctx.lineTo(px(x), py(arena.height / 2));
      ctx.stroke();
    }
    for (let y = -arena.height / 2; y <= arena.height / 2 + 1e-9; y += 0.5) {
      ctx.beginPath();
      ctx.moveTo(px(-arena.width / 2), py(y));
      ctx.lineTo(px(arena.width / 2), py(y));
      ctx.stroke();
    }
    for (const s of world.solids) {
      ctx.fillStyle = `rgb(${s.color.r} ${s.color.g} ${s.color.b})`;
      if (s.kind === 'box') {
        ctx.fillRect(px(s.minX), py(s.maxY), (s.maxX - s.minX) * scale, (s.maxY - s.minY) * scale);
      } else {
        ctx.beginPath();
        ctx.arc(px(s.x), py(s.y), s.radius * scale, 0, Math.PI * 2);
        ctx.fill();
      }
    }
    if (this.#trail.length > 1) {
      ctx.strokeStyle = '#f57c00';
      ctx.lineWidth = 2;
      ctx.beginPath();
      this.#trail.forEach((p, i) =>
        i === 0 ? ctx.moveTo(px(p.x), py(p.y)) : ctx.lineTo(px(p.x), py(p.y)),
      );
      ctx.stroke();
    }
    if (goal !== undefined) {
      ctx.strokeStyle = '#d81b60';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(px(goal.x), py(goal.y), 6, 0, Math.PI * 2);
      ctx.stroke();
    }
    for (const robot of world.robots) {
      const x = px(robot.x);
      const y = py(robot.y);
      const r = Math.max(4, robot.radius * scale);
      ctx.save();
      ctx.translate(x, y);
      ctx.rotate(-robot.yaw);
      ctx.fillStyle = robot.id === robotId ? '#f4b400' : '#4285f4';
      ctx.strokeStyle = '#263238';
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(r * 1.3, 0);
      ctx.lineTo(-r, r * 0.9);
      ctx.lineTo(-r, -r * 0.9);
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
      ctx.restore();
    }
    ctx.fillStyle = '#6b7a8c';
    ctx.font = '11px system-ui, sans-serif';
    ctx.fillText('+x →', w - 40, h - 2);
    ctx.fillText('+y ↑', 2, 10);
  }
}
