import {
  angleDifference,
  HalError,
  V1_ROBOT,
  maxLinearSpeedMPerS,
  minLinearSpeedMPerS,
  toHalError,
} from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer, PlanarPose, ScopedLogger } from '@hal/types';
import { callWithTimeout } from './call-with-timeout.js';
import { decideFollowerAction, slotPosition } from './formation.js';
import type { FollowerAction } from './formation.js';
import { resolveOptions } from './leader-follower-options.js';
import type {
  FollowerReport,
  FormationEndReason,
  FormationReport,
  LeaderFollowerOptions,
  ResolvedOptions,
} from './leader-follower-options.js';
import { selectMembers } from './members.js';
import type { FleetMember } from './members.js';
import { readPose } from './read-pose.js';
import type { FleetScheduler } from './scheduler.js';

interface Busy {
  target: { x: number; y: number } | undefined;
  stopping: boolean;
}

/**
 * Followers keep their formation slots around a moving leader. A control loop at `periodMs`
 * reads the leader's pose, works out each follower's slot (its offset turned by the leader's
 * heading) and sends an idle follower that is out of its slot there with the HAL's own `moveTo`
 * (so each robot's limits and validation apply), interrupting a move whose slot has since moved
 * away. The loop ends on {@link stop}, on any member's e-stop, when the leader is lost, or (by
 * default) once the leader has stopped and every follower is in its slot. You drive the leader.
 */
export class LeaderFollower {
  /** Settles with the report when the formation ends (never rejects). */
  readonly done: Promise<FormationReport>;
  readonly #o: ResolvedOptions;
  readonly #leader: FleetMember;
  readonly #followers: FleetMember[];
  readonly #scheduler: FleetScheduler;
  readonly #logger: ScopedLogger;
  readonly #busy = new Map<string, Busy>();
  readonly #lastResult = new Map<string, HALToolResult>();
  readonly #lastPose = new Map<string, PlanarPose>();
  #resolve!: (report: FormationReport) => void;
  #timer: unknown;
  #ticking = false;
  #finished = false;
  #ticks = 0;
  #leaderPose: PlanarPose | undefined;
  #leaderRef: PlanarPose | undefined;
  #leaderMovedAt = 0;
  #leaderFailures = 0;
  #leaderHasMoved = false;

  constructor(
    members: readonly FleetMember[],
    options: LeaderFollowerOptions,
    scheduler: FleetScheduler,
    logger: ScopedLogger,
  ) {
    this.#o = resolveOptions(options);
    const followerIds = Object.keys(this.#o.formation);
    if (followerIds.length === 0) {
      throw new HalError('INVALID_PARAMETER', 'a formation needs at least one follower', {
        details: { parameter: 'formation' },
      });
    }
    if (followerIds.includes(this.#o.leader)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `the leader "${this.#o.leader}" cannot follow itself`,
        {
          details: { parameter: 'formation', device: this.#o.leader },
        },
      );
    }
    const [leader] = selectMembers(members, [this.#o.leader]);
    this.#leader = leader as FleetMember;
    this.#followers = selectMembers(members, followerIds);
    this.#scheduler = scheduler;
    this.#logger = logger;
    this.done = new Promise((resolve) => (this.#resolve = resolve));
  }

  /** The follower ids. */
  get followers(): string[] {
    return this.#followers.map((f) => f.id);
  }

  /** Whether the control loop still runs. */
  get running(): boolean {
    return !this.#finished;
  }

  /** Each follower's slot for the leader's last known pose (empty before the first pose). */
  slots(): Record<string, { x: number; y: number }> {
    const leader = this.#leaderPose;
    const out: Record<string, { x: number; y: number }> = {};
    if (leader === undefined) return out;
    for (const f of this.#followers) {
      out[f.id] = slotPosition(leader, this.#o.formation[f.id] as { x: number; y: number });
    }
    return out;
  }

  /**
   * Reads where the leader starts from (bounded by `readTimeoutMs`), so that a motion commanded
   * after this counts as the leader moving however fast it runs: a fast-clock simulator finishes
   * a whole move inside the call, before any tick could see it under way. A failed read leaves
   * the reference to the first tick.
   */
  async anchor(): Promise<void> {
    try {
      this.#noteLeader(await this.#read(this.#leader));
    } catch (thrown) {
      this.#logger.warn('no leader pose at the start', { error: toHalError(thrown).message });
    }
  }

  /** Starts the control loop (its first tick runs at once). */
  start(): this {
    this.#leaderMovedAt = this.#scheduler.now();
    this.#timer = this.#scheduler.setTimeout(() => void this.#tick(), 0);
    return this;
  }

  /** Ends the formation and stops every follower; resolves with the report. */
  stop(): Promise<FormationReport> {
    return this.#finish('stopped');
  }

  /** Ends the formation because `device` is e-stopped; stops the followers. */
  endForEstop(device: string): Promise<FormationReport> {
    return this.#finish('estop', device);
  }

  async #tick(): Promise<void> {
    if (this.#finished) return;
    this.#timer = this.#scheduler.setTimeout(() => void this.#tick(), this.#o.periodMs);
    if (this.#ticking) return; // the previous tick still waits for poses
    this.#ticking = true;
    try {
      await this.#step();
    } catch (thrown) {
      this.#logger.error('formation tick failed', { error: toHalError(thrown).message });
    } finally {
      this.#ticking = false;
    }
  }

  async #step(): Promise<void> {
    this.#ticks += 1;
    const stopped = [this.#leader, ...this.#followers].find((m) =>
      m.hal.safety.isEmergencyStopped(),
    );
    if (stopped !== undefined) {
      await this.#finish('estop', stopped.id);
      return;
    }
    let leader: PlanarPose;
    try {
      leader = await this.#read(this.#leader);
      this.#leaderFailures = 0;
    } catch (thrown) {
      this.#leaderFailures += 1;
      this.#logger.warn('no leader pose', { error: toHalError(thrown).message });
      if (this.#leaderFailures >= this.#o.maxLeaderFailures) await this.#finish('leader-lost');
      return;
    }
    if (this.#finished) return;
    this.#noteLeader(leader);
    const now = this.#scheduler.now();
    const leaderStill = now - this.#leaderMovedAt >= this.#o.leaderStillMs;
    const slots = this.slots();
    const idle = this.#followers.filter((f) => !this.#busy.has(f.id));
    this.#retarget(slots);
    const actions = await Promise.all(
      idle.map(async (f): Promise<FollowerAction | undefined> => {
        try {
          const pose = await this.#read(f);
          return decideFollowerAction({
            pose,
            slot: slots[f.id] as { x: number; y: number },
            leaderYaw: leader.yaw,
            toleranceM: this.#o.toleranceM,
            headingToleranceRad: (this.#o.headingToleranceDeg * Math.PI) / 180,
            alignHeading: this.#o.alignHeading,
          });
        } catch {
          return undefined; // unread this tick: try again next tick
        }
      }),
    );
    if (this.#finished) return;
    idle.forEach((f, i) => {
      const action = actions[i];
      if (action !== undefined && action.kind !== 'hold') this.#issue(f, action);
    });
    if (!this.#o.stopWhenLeaderStops || !this.#leaderHasMoved || !leaderStill) return;
    const settled =
      this.#busy.size === 0 &&
      idle.length === this.#followers.length &&
      actions.every((a) => a?.kind === 'hold');
    if (settled) await this.#finish('leader-stopped');
    else if (now - this.#leaderMovedAt >= this.#o.leaderStillMs + this.#o.settleTimeoutMs) {
      await this.#finish('settle-timeout');
    }
  }

  #read(member: FleetMember): Promise<PlanarPose> {
    return readPose(member.hal, member.id, this.#o.readTimeoutMs, this.#scheduler).then((p) => {
      this.#lastPose.set(member.id, p);
      return p;
    });
  }

  /** Tracks when the leader last moved (1 mm or 0.5 degrees from where it was). */
  #noteLeader(pose: PlanarPose): void {
    this.#leaderPose = pose;
    const ref = this.#leaderRef;
    const turned = ref === undefined ? 0 : Math.abs(angleDifference(pose.yaw, ref.yaw));
    if (
      ref === undefined ||
      Math.hypot(pose.x - ref.x, pose.y - ref.y) > 0.001 ||
      turned > 0.0087
    ) {
      if (ref !== undefined) this.#leaderHasMoved = true;
      this.#leaderRef = pose;
      this.#leaderMovedAt = this.#scheduler.now();
    }
  }

  /** Interrupts a follower's move whose target is now far from its slot. */
  #retarget(slots: Record<string, { x: number; y: number }>): void {
    for (const f of this.#followers) {
      const busy = this.#busy.get(f.id);
      const slot = slots[f.id];
      if (busy?.target === undefined || busy.stopping || slot === undefined) continue;
      if (Math.hypot(busy.target.x - slot.x, busy.target.y - slot.y) <= this.#o.retargetM) continue;
      busy.stopping = true;
      void f.hal.locomotion.stop().catch(() => undefined);
    }
  }

  #issue(f: FleetMember, action: Exclude<FollowerAction, { kind: 'hold' }>): void {
    const hal = f.hal;
    const busy: Busy = {
      target: action.kind === 'moveTo' ? { x: action.x, y: action.y } : undefined,
      stopping: false,
    };
    this.#busy.set(f.id, busy);
    const speed = this.#speedFor(hal);
    const run =
      action.kind === 'moveTo'
        ? () => hal.locomotion.moveTo(action.x, action.y, 0, speed)
        : () => hal.locomotion.rotate(action.direction, action.degrees);
    void callWithTimeout(run, {
      mode: hal.mode,
      device: f.id,
      timeoutMs: this.#o.callTimeoutMs,
      scheduler: this.#scheduler,
    }).then((result) => {
      if (this.#busy.get(f.id) === busy) this.#busy.delete(f.id);
      this.#lastResult.set(f.id, result);
      if (!result.success && result.code !== 'INTERRUPTED') {
        this.#logger.warn('follower move failed', {
          device: f.id,
          code: result.code,
          error: result.error,
        });
      }
      if (result.code === 'EMERGENCY_STOPPED') void this.#finish('estop', f.id);
    });
  }

  /** The configured follower speed within this robot's slowest..top speed. */
  #speedFor(hal: HardwareAbstractionLayer): number | undefined {
    const wanted = this.#o.speedMPerS;
    if (wanted === undefined) return undefined;
    const config = hal.robotConfig ?? V1_ROBOT;
    return Math.min(maxLinearSpeedMPerS(config), Math.max(minLinearSpeedMPerS(config), wanted));
  }

  async #finish(reason: FormationEndReason, estopDevice?: string): Promise<FormationReport> {
    if (this.#finished) return this.done;
    this.#finished = true;
    this.#scheduler.clearTimeout(this.#timer);
    if (reason !== 'leader-stopped') {
      // every follower in the same tick; a slow one delays only the report
      await Promise.all(
        this.#followers.map((f) =>
          callWithTimeout(() => f.hal.locomotion.stop(), {
            mode: f.hal.mode,
            device: f.id,
            timeoutMs: this.#o.readTimeoutMs,
            scheduler: this.#scheduler,
          }),
        ),
      );
    }
    await Promise.all(this.#followers.map((f) => this.#read(f).catch(() => undefined)));
    const report: FormationReport = {
      reason,
      leader: this.#leader.id,
      followers: this.#followers.map((f) => this.#followerReport(f.id)),
      ticks: this.#ticks,
    };
    if (estopDevice !== undefined) report.estopDevice = estopDevice;
    if (this.#leaderPose !== undefined) report.leaderPose = this.#leaderPose;
    this.#logger.info('formation ended', { reason, leader: this.#leader.id });
    this.#resolve(report);
    return report;
  }

  #followerReport(device: string): FollowerReport {
    const offset = this.#o.formation[device] as { x: number; y: number };
    const report: FollowerReport = { device, offset: { x: offset.x, y: offset.y } };
    const slot = this.slots()[device];
    const pose = this.#lastPose.get(device);
    const last = this.#lastResult.get(device);
    if (slot !== undefined) report.slot = slot;
    if (pose !== undefined) report.pose = pose;
    if (slot !== undefined && pose !== undefined) {
      report.errorM = Math.hypot(slot.x - pose.x, slot.y - pose.y);
    }
    if (last !== undefined) report.lastResult = last;
    return report;
  }
}
