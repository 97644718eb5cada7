import type { World } from '@hal/simulation';

/** A top view of the arena: solids, the robot's trail, the goal and the robot, on a 2D canvas. */
export class TrajectoryPlot {
  readonly #canvas: HTMLCanvasElement;
  readonly #ctx: CanvasRenderingContext2D;
  #trail: Array<{ x: number; y: number }> = [];
  #scale = 1;

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

  /** The world point (metres) under a point of the canvas as shown, in client pixels. */
  toWorld(clientX: number, clientY: number): { x: number; y: number } {
    const rect = this.#canvas.getBoundingClientRect();
    const cx = ((clientX - rect.left) / rect.width) * this.#canvas.width;
    const cy = ((clientY - rect.top) / rect.height) * this.#canvas.height;
    return {
      x: (cx - this.#canvas.width / 2) / this.#scale,
      y: (this.#canvas.height / 2 - cy) / this.#scale,
    };
  }

  get trail(): ReadonlyArray<{ x: number; y: number }> {
    return this.#trail;
  }

  draw(
    world: World,
    robotId: string,
    goal: { x: number; y: number } | undefined,
    path?: ReadonlyArray<{ x: number; y: number }>,
    colorOf?: (robotId: string) => string | undefined,
  ): void {
    const ctx = this.#ctx;
    const { width: w, height: h } = this.#canvas;
    const { arena } = world.map;
    // Sizes below are for a canvas shown about 250 px wide; k scales them to its real width.
    const k = w / 250;
    const pad = 6 * k;
    const scale = Math.min((w - 2 * pad) / arena.width, (h - 2 * pad) / arena.height);
    this.#scale = scale;
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
    ctx.lineWidth = 0.6 * k;
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
      ctx.lineWidth = 1.6 * k;
      ctx.beginPath();
      this.#trail.forEach((p, i) =>
        i === 0 ? ctx.moveTo(px(p.x), py(p.y)) : ctx.lineTo(px(p.x), py(p.y)),
      );
      ctx.stroke();
    }
    if (path !== undefined && path.length > 1) {
      ctx.strokeStyle = '#1565c0';
      ctx.lineWidth = 1.2 * k;
      ctx.setLineDash([4 * k, 3 * k]);
      ctx.beginPath();
      path.forEach((p, i) =>
        i === 0 ? ctx.moveTo(px(p.x), py(p.y)) : ctx.lineTo(px(p.x), py(p.y)),
      );
      ctx.stroke();
      ctx.setLineDash([]);
    }
    if (goal !== undefined) {
      ctx.strokeStyle = '#d81b60';
      ctx.lineWidth = 1.6 * k;
      ctx.beginPath();
      ctx.arc(px(goal.x), py(goal.y), 4 * k, 0, Math.PI * 2);
      ctx.stroke();
    }
    for (const robot of world.robots) {
      const x = px(robot.x);
      const y = py(robot.y);
      const r = Math.max(4 * k, robot.radius * scale);
      ctx.save();
      ctx.translate(x, y);
      ctx.rotate(-robot.yaw);
      const selected = robot.id === robotId;
      ctx.fillStyle = colorOf?.(robot.id) ?? (selected ? '#f4b400' : '#4285f4');
      ctx.strokeStyle = '#263238';
      // The robot the page drives has the heavier outline.
      ctx.lineWidth = (selected ? 2 : 1) * k;
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
    ctx.font = `${Math.round(9 * k)}px system-ui, sans-serif`;
    ctx.textAlign = 'right';
    ctx.fillText('+x →', w - pad - 4 * k, h - pad - 4 * k);
    ctx.textAlign = 'left';
    ctx.fillText('+y ↑', pad + 4 * k, pad + 11 * k);
  }
}
