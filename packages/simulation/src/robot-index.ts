import type { SimRobot } from './robot/sim-robot.js';

/** Offset that keeps cell coordinates positive in a key. */
const OFFSET = 2 ** 20;

/**
 * Where a world's robots were at one instant, binned in square cells, so that the robots near a
 * point are found without looking at all of them. Built from every robot brought up to the clock;
 * a robot can since have moved at most {@link staleness}, which every query adds to its radius.
 */
export class RobotIndex {
  /** When the positions were taken, µs. */
  readonly builtUs: number;
  /** The highest top speed among the robots, m/s, and the largest footprint radius, m. */
  readonly maxSpeedMps: number;
  readonly maxRadius: number;
  readonly #maxStep: number;
  readonly #cellM: number;
  readonly #cells = new Map<number, number[]>();

  constructor(robots: readonly SimRobot[], nowUs: number, cellM = 0.5) {
    this.builtUs = nowUs;
    this.#cellM = cellM;
    let speed = 0;
    let radius = 0;
    let step = 0;
    for (let i = 0; i < robots.length; i += 1) {
      const robot = robots[i] as SimRobot;
      speed = Math.max(speed, robot.maxSpeedMps);
      radius = Math.max(radius, robot.radius);
      step = Math.max(step, robot.stepLengthM);
      const key = this.#key(Math.floor(robot.x / cellM), Math.floor(robot.y / cellM));
      const cell = this.#cells.get(key);
      if (cell === undefined) this.#cells.set(key, [i]);
      else cell.push(i);
    }
    this.maxSpeedMps = speed;
    this.maxRadius = radius;
    this.#maxStep = step;
  }

  /** How far any robot can be from where the index put it, at `nowUs`, metres. */
  staleness(nowUs: number): number {
    return this.maxSpeedMps * (Math.max(0, nowUs - this.builtUs) / 1e6) + this.#maxStep;
  }

  /** The robots (indices, ascending) put within `radius` of (x, y), and maybe a few more. */
  near(x: number, y: number, radius: number): number[] {
    const c = this.#cellM;
    const found: number[] = [];
    const x0 = Math.floor((x - radius) / c);
    const x1 = Math.floor((x + radius) / c);
    const y0 = Math.floor((y - radius) / c);
    const y1 = Math.floor((y + radius) / c);
    for (let cx = x0; cx <= x1; cx += 1) {
      for (let cy = y0; cy <= y1; cy += 1) {
        const cell = this.#cells.get(this.#key(cx, cy));
        if (cell !== undefined) for (const i of cell) found.push(i);
      }
    }
    return found.sort((a, b) => a - b);
  }

  #key(cx: number, cy: number): number {
    return (cx + OFFSET) * 2 ** 21 + (cy + OFFSET);
  }
}
