import { getStepsPerCm } from '../geometry.js';
import { integrateOdometry } from '../odometry.js';
import type { PlanarPoseCm } from '../odometry.js';
import type { StepPlan } from '../planner.js';
import { normalizeAngle } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { WheelScale } from './wheel-scale.js';

/** The heading is wrapped and its sine and cosine recomputed every this many master steps. */
const RESYNC_STEPS = 4096;
/** Plans whose step pattern repeats within this many master steps are advanced by whole periods. */
const MAX_PERIOD = 4096;

function gcd(a: number, b: number): number {
  while (b !== 0) [a, b] = [b, a % b];
  return a;
}

/** Where the pattern's periods are counted from, and what one period does (robot frame, cm, rad). */
interface Periods {
  /** Master steps per period. */
  length: number;
  k: number;
  xCm: number;
  yCm: number;
  heading: number;
  cos: number;
  sin: number;
  slave: number;
  left: number;
  right: number;
  dx: number;
  dy: number;
  dth: number;
}

/** One step of a plan as a rigid motion in the robot frame (cm, rad): both wheels, or the master alone. */
interface StepMotion {
  dl: number;
  dr: number;
  dx: number;
  dy: number;
  dth: number;
  cos: number;
  sin: number;
}

/** Each step as the nominal wheel travel (a body without error). */
const NOMINAL: WheelScale = { left: 1, right: 1 };

function stepMotion(dl: number, dr: number, config: RobotConfig, scale: WheelScale): StepMotion {
  // The firmware's formula for these wheel deltas, from the origin: the motion in the robot frame
  // (each wheel's travel on the ground scaled by the body's error, when it has one).
  const gl = dl * scale.left;
  const gr = dr * scale.right;
  const p = integrateOdometry({ xCm: 0, yCm: 0, headingRad: 0 }, gl, gr, config);
  const perCm = getStepsPerCm(config);
  const dth = (gr / perCm - gl / perCm) / config.wheelBaseCm;
  return { dl, dr, dx: p.xCm, dy: p.yCm, dth, cos: Math.cos(dth), sin: Math.sin(dth) };
}

/**
 * Odometry one whole step at a time. A plan's master wheel steps at every one of its step
 * instants and the slave, by Bresenham, at some of the same instants, so every step is one of two
 * rigid motions, computed once per plan with the firmware's formula; a step then costs a few
 * multiplications and no trigonometry. The pose is that of integrating each step on its own,
 * which is what the firmware's odometry converges to as its polls get finer.
 */
export class StepOdometry {
  #xCm: number;
  #yCm: number;
  #heading: number;
  #cos: number;
  #sin: number;
  #left = 0;
  #right = 0;
  #both: StepMotion | undefined;
  #masterOnly: StepMotion | undefined;
  #masterTerm = 1;
  #slaveTerm = 0;
  /** Master and slave steps the current plan has made. */
  #k = 0;
  #slave = 0;
  #periods: Periods | undefined;
  #scale: WheelScale = NOMINAL;

  constructor(start: PlanarPoseCm) {
    this.#xCm = start.xCm;
    this.#yCm = start.yCm;
    this.#heading = start.headingRad;
    this.#cos = Math.cos(this.#heading);
    this.#sin = Math.sin(this.#heading);
  }

  get pose(): PlanarPoseCm {
    return { xCm: this.#xCm, yCm: this.#yCm, headingRad: normalizeAngle(this.#heading) };
  }
  get xCm(): number {
    return this.#xCm;
  }
  get yCm(): number {
    return this.#yCm;
  }
  /** Absolute wheel positions, steps. */
  get left(): number {
    return this.#left;
  }
  get right(): number {
    return this.#right;
  }
  /** Master steps the current plan has made. */
  get masterSteps(): number {
    return this.#k;
  }
  /** The most the centre moves in one master step of the current plan, cm. */
  get maxStepCm(): number {
    const length = (m: StepMotion | undefined) => (m === undefined ? 0 : Math.hypot(m.dx, m.dy));
    // Steps of both wheels happen only if the slave steps at all; the master's alone only if
    // the slave makes fewer steps than the master.
    const both = this.#slaveTerm > 0 ? length(this.#both) : 0;
    const alone = this.#slaveTerm < this.#masterTerm ? length(this.#masterOnly) : 0;
    return Math.max(both, alone);
  }

  /**
   * Starts counting the steps of a new plan (with the geometry of `config`); `scale` is what each
   * wheel's step does on the ground, relative to the nominal (default exactly that).
   */
  begin(plan: StepPlan, config: RobotConfig, scale: WheelScale = NOMINAL): void {
    this.#scale = scale;
    this.#masterTerm = plan.masterTerm === 0 ? 1 : plan.masterTerm;
    this.#slaveTerm = plan.slaveTerm;
    this.#k = 0;
    this.#slave = 0;
    this.#resync();
    this.#geometry(plan, config);
    this.#countPeriods();
  }

  /** The geometry changed (`set_config`): the steps still to come use the new one. */
  reconfigure(plan: StepPlan, config: RobotConfig): void {
    this.#geometry(plan, config);
    this.#resync();
    this.#countPeriods();
  }

  /**
   * The Bresenham pattern repeats every masterTerm / gcd(masterTerm, slaveTerm) master steps, and
   * so does the rigid motion of one period. When the period is short, the pose at the end of the
   * n-th period after here is computed in closed form from n (a sum of rotated copies of one
   * period's motion), and only the steps within a period are walked one by one. Both depend only
   * on the step number, never on how the walk is split, so the pose stays the same bits however
   * often the robot is read.
   */
  #countPeriods(): void {
    this.#periods = undefined;
    const M = this.#masterTerm;
    const S = this.#slaveTerm;
    const length = M / gcd(M, S);
    if (!(length <= MAX_PERIOD)) return;
    const here = {
      length,
      k: this.#k,
      xCm: this.#xCm,
      yCm: this.#yCm,
      heading: this.#heading,
      cos: this.#cos,
      sin: this.#sin,
      slave: this.#slave,
      left: this.#left,
      right: this.#right,
    };
    // One period walked from the origin gives its motion.
    this.#xCm = 0;
    this.#yCm = 0;
    this.#heading = 0;
    this.#cos = 1;
    this.#sin = 0;
    this.walkTo(this.#k + length);
    const period = { ...here, dx: this.#xCm, dy: this.#yCm, dth: this.#heading };
    this.#k = here.k;
    this.#xCm = here.xCm;
    this.#yCm = here.yCm;
    this.#heading = here.heading;
    this.#cos = here.cos;
    this.#sin = here.sin;
    this.#slave = here.slave;
    this.#left = here.left;
    this.#right = here.right;
    this.#periods = period;
  }

  /** Jumps to the end of the n-th period (n >= 1) in closed form. */
  #toPeriod(p: Periods, n: number): void {
    const k = p.k + n * p.length;
    // Sum over j < n of the period's motion turned by j * dth: t * sin(n a) / sin(a) * e^(i (n-1) a),
    // with a = dth / 2 (n copies when the period does not turn).
    const a = p.dth / 2;
    const scale = a === 0 ? n : Math.sin(n * a) / Math.sin(a);
    const b = (n - 1) * a;
    const cb = Math.cos(b);
    const sb = Math.sin(b);
    const X = scale * (p.dx * cb - p.dy * sb);
    const Y = scale * (p.dx * sb + p.dy * cb);
    this.#xCm = p.xCm + p.cos * X - p.sin * Y;
    this.#yCm = p.yCm + p.sin * X + p.cos * Y;
    this.#heading = normalizeAngle(p.heading + n * p.dth);
    this.#cos = Math.cos(this.#heading);
    this.#sin = Math.sin(this.#heading);
    const slave = Math.floor((k * this.#slaveTerm) / this.#masterTerm);
    const pairs = slave - p.slave;
    const alone = k - p.k - pairs;
    const both = this.#both as StepMotion;
    const single = this.#masterOnly as StepMotion;
    this.#left = p.left + pairs * both.dl + alone * single.dl;
    this.#right = p.right + pairs * both.dr + alone * single.dr;
    this.#slave = slave;
    this.#k = k;
  }

  #geometry(plan: StepPlan, config: RobotConfig): void {
    const ml = plan.leftIsMaster ? plan.leftSign : 0;
    const mr = plan.leftIsMaster ? 0 : plan.rightSign;
    this.#masterOnly = stepMotion(ml, mr, config, this.#scale);
    this.#both = stepMotion(plan.leftSign, plan.rightSign, config, this.#scale);
  }

  /** The motion of the next master step (without taking it). */
  next(): StepMotion {
    const k = this.#k + 1;
    const slave = Math.floor((k * this.#slaveTerm) / this.#masterTerm);
    return (slave > this.#slave ? this.#both : this.#masterOnly) as StepMotion;
  }

  /** Where the centre would be after the next master step, cm (nothing changes). */
  peek(into: { xCm: number; yCm: number; headingRad: number }): void {
    const m = this.next();
    into.xCm = this.#xCm + this.#cos * m.dx - this.#sin * m.dy;
    into.yCm = this.#yCm + this.#sin * m.dx + this.#cos * m.dy;
    into.headingRad = this.#heading + m.dth;
  }

  /** Takes master steps up to the plan's k-th (k above the steps made). */
  walkTo(k: number): void {
    if (k <= this.#k) return;
    const p = this.#periods;
    if (p !== undefined) {
      const n = Math.floor((k - p.k) / p.length);
      if (n > Math.floor((this.#k - p.k) / p.length)) this.#toPeriod(p, n);
      if (k <= this.#k) return;
    }
    const both = this.#both as StepMotion;
    const alone = this.#masterOnly as StepMotion;
    const M = this.#masterTerm;
    const S = this.#slaveTerm;
    let x = this.#xCm;
    let y = this.#yCm;
    let th = this.#heading;
    let c = this.#cos;
    let s = this.#sin;
    let slave = this.#slave;
    // Bresenham's remainder: k * S - slave * M, so that the slave steps when it reaches M
    // (the same integers as floor(k * S / M), without a division per step).
    let rem = this.#k * S - slave * M;
    let bothSteps = 0;
    for (let i = this.#k + 1; i <= k; i += 1) {
      rem += S;
      let m = alone;
      if (rem >= M) {
        rem -= M;
        slave += 1;
        bothSteps += 1;
        m = both;
      }
      x += c * m.dx - s * m.dy;
      y += s * m.dx + c * m.dy;
      th += m.dth;
      const c2 = c * m.cos - s * m.sin;
      s = s * m.cos + c * m.sin;
      c = c2;
      if (i % RESYNC_STEPS === 0) {
        th = normalizeAngle(th);
        c = Math.cos(th);
        s = Math.sin(th);
      }
    }
    const steps = k - this.#k;
    this.#left += bothSteps * both.dl + (steps - bothSteps) * alone.dl;
    this.#right += bothSteps * both.dr + (steps - bothSteps) * alone.dr;
    this.#xCm = x;
    this.#yCm = y;
    this.#heading = th;
    this.#cos = c;
    this.#sin = s;
    this.#slave = slave;
    this.#k = k;
  }

  #resync(): void {
    this.#heading = normalizeAngle(this.#heading);
    this.#cos = Math.cos(this.#heading);
    this.#sin = Math.sin(this.#heading);
  }
}
