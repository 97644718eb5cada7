import {
  failureResult,
  HalBoundary,
  maxLinearSpeedMPerS,
  normalizeAngle,
  V1_ROBOT,
} from '@hal/types';
import type { CallName, HALToolResult, LocomotionInterface, Pose } from '@hal/types';
import type { GuardContext } from './guard-context.js';
import {
  blindResult,
  blindTripResult,
  cancelledResult,
  obstacleResult,
  reverseRefusal,
} from './guard-outcomes.js';
import { combineLegs } from './legs.js';
import type { LegPlan } from './legs.js';
import type { Sight, Sighting } from './sighting.js';
import { Watcher } from './watcher.js';
import type { Trip } from './watcher.js';

/** A leg shorter than this, metres, is the rest of the motion (rounding). */
const REST_M = 1e-4;

/**
 * The guard's locomotion: forward motions (moveForward, moveTo, drive with positive wheel power)
 * are looked ahead of before they start and driven in legs no longer than the free distance seen
 * less the stand-off, with a watcher looking at the camera's rate while a leg runs; a reverse
 * passes unwatched (said once) or is refused; a turn in place passes; `stop` goes straight through.
 */
export class GuardedLocomotion implements LocomotionInterface {
  readonly #ctx: GuardContext;
  readonly #boundary: HalBoundary;
  /** Bumped by every stop, e-stop and motion: a guard loop of an older motion gives up. */
  #epoch = 0;
  #watcher: Watcher | undefined;
  #reverseSaid = false;
  /** When the last motion through the guard ended (ms, `Date.now()`). */
  #motionEndedAt = 0;

  constructor(ctx: GuardContext) {
    this.#ctx = ctx;
    const hal = ctx.hal;
    this.#boundary = new HalBoundary({
      get mode() {
        return hal.mode;
      },
      config: () => hal.robotConfig ?? V1_ROBOT,
      isEmergencyStopped: () => hal.safety.isEmergencyStopped(),
      isReady: () => hal.isReady(),
    });
  }

  get #hal(): LocomotionInterface {
    return this.#ctx.hal.locomotion;
  }

  /** Ends what the guard does for the motion under way (a stop, an e-stop, a newer motion). */
  cancel(): void {
    this.#epoch += 1;
    this.#watcher?.stop();
    this.#watcher = undefined;
  }

  stop(): Promise<HALToolResult> {
    const stopping = this.#ended(this.#hal.stop());
    this.cancel();
    return stopping;
  }

  getPose(): Promise<Pose> {
    return this.#hal.getPose();
  }

  rotate(direction: 'left' | 'right', degrees: number): Promise<HALToolResult> {
    // a turn in place sweeps only the body's own footprint (a disc); nothing ahead is reached
    this.cancel();
    return this.#ended(this.#hal.rotate(direction, degrees));
  }

  /** `motion`, noting when it ended (a look after it waits for a frame that shows it done). */
  #ended(motion: Promise<HALToolResult>): Promise<HALToolResult> {
    return motion.finally(() => {
      this.#motionEndedAt = Date.now();
    });
  }

  /** A look ahead, once a frame taken after the last motion can have come. */
  async #look(sight: Sight): Promise<Sighting> {
    const { settleMs, framePeriodMs } = this.#ctx.settings;
    const settle = settleMs ?? (this.#ctx.hal.mode === 'simulation' ? 0 : 2 * framePeriodMs);
    const wait = this.#motionEndedAt + settle - Date.now();
    if (wait > 0) await new Promise((resolve) => setTimeout(resolve, wait));
    return sight.look();
  }

  moveBackward(distanceCm: number): Promise<HALToolResult> {
    this.cancel();
    if (!this.#valid('moveBackward', { distanceCm })) return this.#hal.moveBackward(distanceCm);
    return this.#reverse('moveBackward', () => this.#ended(this.#hal.moveBackward(distanceCm)));
  }

  async moveForward(distanceCm: number): Promise<HALToolResult> {
    this.cancel();
    const whole = () => this.#ended(this.#hal.moveForward(distanceCm));
    if (!this.#valid('moveForward', { distanceCm })) return whole();
    const epoch = this.#epoch;
    const sight = await this.#sight('moveForward');
    if (sight === undefined) return whole();
    let remainingCm = distanceCm;
    return this.#legs('moveForward', epoch, sight, {
      remainingM: () => Promise.resolve(remainingCm / 100),
      run: (legM, final) => {
        const cm = final ? remainingCm : legM * 100;
        remainingCm -= cm;
        return this.#ended(this.#hal.moveForward(cm));
      },
    });
  }

  async moveTo(x: number, y: number, z: number, speed?: number): Promise<HALToolResult> {
    this.cancel();
    const go = (px: number, py: number) =>
      this.#ended(
        speed === undefined ? this.#hal.moveTo(px, py, z) : this.#hal.moveTo(px, py, z, speed),
      );
    if (!this.#valid('moveTo', { x, y, z, speed })) return go(x, y);
    const epoch = this.#epoch;
    const sight = await this.#sight('moveTo');
    if (sight === undefined) return go(x, y);
    let pose: Pose;
    try {
      pose = await this.#hal.getPose();
    } catch (error) {
      return failureResult(this.#ctx.hal.mode, Date.now(), error);
    }
    const dx = x - pose.position.x;
    const dy = y - pose.position.y;
    if (Math.hypot(dx, dy) < 1e-3) return go(x, y);
    // face the point first (a turn in place), so the camera looks along the way
    const turnDeg = (normalizeAngle(Math.atan2(dy, dx) - pose.rotation.yaw) * 180) / Math.PI;
    if (Math.abs(turnDeg) > 1) {
      const turned = await this.#ended(
        this.#hal.rotate(turnDeg > 0 ? 'left' : 'right', Math.abs(turnDeg)),
      );
      if (!turned.success) return turned;
      if (epoch !== this.#epoch) return this.#cancelled('moveTo');
    }
    const where = async () => {
      const p = await this.#hal.getPose();
      const ex = x - p.position.x;
      const ey = y - p.position.y;
      return { p, ex, ey, left: Math.hypot(ex, ey) };
    };
    return this.#legs('moveTo', epoch, sight, {
      remainingM: async () => (await where()).left,
      run: async (legM, final) => {
        if (final) return go(x, y);
        const { p, ex, ey, left } = await where();
        return go(p.position.x + (ex / left) * legM, p.position.y + (ey / left) * legM);
      },
    });
  }

  async drive(left: number, right: number, durationMs?: number): Promise<HALToolResult> {
    this.cancel();
    const whole = () =>
      this.#ended(
        durationMs === undefined
          ? this.#hal.drive(left, right)
          : this.#hal.drive(left, right, durationMs),
      );
    if (!this.#valid('drive', { left, right, durationMs })) return whole();
    const power = (left + right) / 2;
    // a turn in place passes; a reverse is watched by nothing
    if (power === 0) return whole();
    if (power < 0) return this.#reverse('drive', whole);
    const epoch = this.#epoch;
    const sight = await this.#sight('drive');
    if (sight === undefined) return whole();
    if (durationMs === undefined) return this.#driveOn(epoch, sight, whole);
    const speed = (power / 255) * maxLinearSpeedMPerS(this.#ctx.hal.robotConfig ?? V1_ROBOT);
    let remainingMs = durationMs;
    return this.#legs('drive', epoch, sight, {
      remainingM: () => Promise.resolve((remainingMs / 1000) * speed),
      run: (legM, final) => {
        const ms = final ? remainingMs : Math.max(1, Math.floor((legM / speed) * 1000));
        remainingMs -= ms;
        return this.#ended(this.#hal.drive(left, right, ms));
      },
    });
  }

  /** Whether the guard takes the call: the HAL is ready, not e-stopped, and the call valid. */
  #valid(call: CallName, args: Record<string, unknown>): boolean {
    try {
      this.#boundary.checkAllowed(call);
      this.#boundary.validate(call, args);
      return true;
    } catch {
      return false; // the HAL answers it, with its own reason
    }
  }

  async #sight(motion: string): Promise<Sight | undefined> {
    const sight = await this.#ctx.sight();
    if (sight === undefined) {
      this.#ctx.record.unguarded(motion, `${motion}: passed unwatched: the guard cannot see`);
    }
    return sight;
  }

  #tooNear(seen: Sighting): boolean {
    return seen.aheadM < this.#ctx.settings.standoffM || (seen.blocked && seen.atEdge);
  }

  async #legs(motion: string, epoch: number, sight: Sight, plan: LegPlan): Promise<HALToolResult> {
    const { standoffM, errorFraction, minLegM } = this.#ctx.settings;
    const start = await this.#hal.getPose().catch(() => undefined);
    const results: HALToolResult[] = [];
    for (;;) {
      let remaining: number;
      let seen: Sighting;
      try {
        remaining = await plan.remainingM();
        seen = await this.#look(sight);
      } catch (error) {
        if (epoch !== this.#epoch) return combineLegs(results) ?? this.#cancelled(motion);
        return this.#blind(motion, results, error);
      }
      if (epoch !== this.#epoch) return combineLegs(results) ?? this.#cancelled(motion);
      const room = seen.aheadM - standoffM - errorFraction * seen.aheadM;
      if (this.#tooNear(seen) || room < Math.min(minLegM, remaining)) {
        return this.#obstacle(motion, seen, results.length === 0 ? 'before' : 'during', start);
      }
      const final = room >= remaining - REST_M;
      const watcher = this.#ctx.settings.watch ? this.#watch(sight) : undefined;
      let result: HALToolResult;
      try {
        result = await plan.run(final ? remaining : room, final);
      } finally {
        watcher?.stop();
        if (this.#watcher === watcher) this.#watcher = undefined;
      }
      results.push(result);
      const trip = watcher?.trip;
      if (trip !== undefined && (!result.success || !final)) {
        return this.#tripped(motion, trip, start);
      }
      if (!result.success || final || epoch !== this.#epoch) return combineLegs(results) ?? result;
    }
  }

  /** A watcher for the leg about to run; it stops the robot when it trips. */
  #watch(sight: Sight): Watcher {
    const { framePeriodMs, blindLimitMs } = this.#ctx.settings;
    const watcher = new Watcher({
      sight,
      periodMs: framePeriodMs,
      blindLimitMs,
      tooNear: (seen) => this.#tooNear(seen),
      onTrip: () => {
        void this.#hal.stop().catch(() => undefined);
      },
    });
    this.#watcher = watcher;
    watcher.start();
    return watcher;
  }

  /** A drive with no end: looked ahead of first, then watched until the next call. */
  async #driveOn(
    epoch: number,
    sight: Sight,
    start: () => Promise<HALToolResult>,
  ): Promise<HALToolResult> {
    let seen: Sighting;
    try {
      seen = await this.#look(sight);
    } catch (error) {
      if (epoch !== this.#epoch) return this.#cancelled('drive');
      return this.#blind('drive', [], error);
    }
    if (epoch !== this.#epoch) return this.#cancelled('drive');
    if (
      this.#tooNear(seen) ||
      seen.aheadM - this.#ctx.settings.standoffM < this.#ctx.settings.minLegM
    ) {
      return this.#obstacle('drive', seen, 'before', undefined);
    }
    const pose = await this.#hal.getPose().catch(() => undefined);
    const result = await start();
    if (!result.success || epoch !== this.#epoch) return result;
    const { framePeriodMs, blindLimitMs } = this.#ctx.settings;
    const watcher = new Watcher({
      sight,
      periodMs: framePeriodMs,
      blindLimitMs,
      tooNear: (s) => this.#tooNear(s),
      onTrip: (trip) => {
        void this.#hal.stop().catch(() => undefined);
        if (this.#watcher === watcher) this.#watcher = undefined;
        void this.#tripped('drive', trip, pose);
      },
    });
    this.#watcher = watcher;
    watcher.start();
    return result;
  }

  async #reverse(motion: string, run: () => Promise<HALToolResult>): Promise<HALToolResult> {
    if (this.#ctx.settings.reverse === 'refuse') return reverseRefusal(this.#ctx, motion);
    const message = 'the guard cannot see behind the robot: a reverse passes unwatched';
    if (!this.#reverseSaid) {
      this.#reverseSaid = true;
      this.#ctx.log.warn(message);
    }
    this.#ctx.record.unguarded(motion, `${motion}: ${message}`);
    return run();
  }

  /** How far the robot went since `start`, metres (0 when a pose cannot be read). */
  async #travelled(start: Pose | undefined): Promise<number> {
    if (start === undefined) return 0;
    const now = await this.#hal.getPose().catch(() => undefined);
    if (now === undefined) return 0;
    return Math.hypot(now.position.x - start.position.x, now.position.y - start.position.y);
  }

  async #obstacle(
    motion: string,
    seen: Sighting,
    when: 'before' | 'during',
    start: Pose | undefined,
  ): Promise<HALToolResult> {
    const travelledM = when === 'before' ? 0 : await this.#travelled(start);
    return obstacleResult(this.#ctx, motion, seen, when, travelledM);
  }

  async #blind(motion: string, results: HALToolResult[], error: unknown): Promise<HALToolResult> {
    return blindResult(this.#ctx, motion, results.length > 0, error);
  }

  async #tripped(motion: string, trip: Trip, start: Pose | undefined): Promise<HALToolResult> {
    if (trip.kind === 'obstacle') return this.#obstacle(motion, trip.sighting, 'during', start);
    return blindTripResult(this.#ctx, motion, trip.sinceMs);
  }

  #cancelled(motion: string): HALToolResult {
    return cancelledResult(this.#ctx, motion);
  }
}
