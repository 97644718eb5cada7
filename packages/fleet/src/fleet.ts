import { EstopLatch, HalError, sanitizeEstopReason, scoped, silentLogger } from '@hal/types';
import type { HardwareAbstractionLayer, Logger, ScopedLogger } from '@hal/types';
import type { FleetCommand } from './commands.js';
import { LeaderFollower } from './leader-follower.js';
import type { LeaderFollowerOptions } from './leader-follower-options.js';
import { checkDeviceId, selectMembers } from './members.js';
import type { FleetMember } from './members.js';
import type { FleetReport, MemberResult } from './report.js';
import { realTimeScheduler } from './scheduler.js';
import type { FleetScheduler } from './scheduler.js';
import {
  DEFAULT_CALL_TIMEOUT_MS,
  checkTimeout,
  memberCallOf,
  refuseAll,
  runOnAll,
} from './synchronized.js';
import type { MemberCall, SynchronizedOptions } from './synchronized.js';

export interface FleetOptions {
  /** The clock of every wait and of the leader-follower loop. Default the wall clock. */
  scheduler?: FleetScheduler;
  logger?: Logger;
  /** Default per-member wait of a synchronized or independent call, ms. Default 60000. */
  callTimeoutMs?: number;
  /** Per-member wait of the fleet e-stop, ms. Default 2000. */
  estopTimeoutMs?: number;
}

/**
 * Several robots, each behind its own HAL, driven in one of three modes:
 * - independent: {@link hal} (or {@link independent}) routes a call to one member;
 * - synchronized: {@link synchronized} issues one command to every member in the same tick and
 *   reports every member's own result together;
 * - leader-follower: {@link leaderFollower} keeps followers in formation around a moving leader.
 * {@link emergencyStop} latches every member at once, and the fleet itself, until
 * {@link resetEmergencyStop}. Browser-safe: no Node imports, any `HardwareAbstractionLayer`s.
 */
export class Fleet {
  readonly scheduler: FleetScheduler;
  readonly #logger: ScopedLogger;
  readonly #callTimeoutMs: number;
  readonly #estopTimeoutMs: number;
  readonly #members = new Map<string, FleetMember>();
  /** The fleet's own latch: set by emergencyStop(), cleared when every member's reset succeeds. */
  readonly #latch = new EstopLatch();
  #formation: LeaderFollower | undefined;

  constructor(members: Iterable<FleetMember> = [], options: FleetOptions = {}) {
    this.scheduler = options.scheduler ?? realTimeScheduler;
    this.#logger = scoped(options.logger ?? silentLogger, 'hal:fleet');
    this.#callTimeoutMs = checkTimeout(options.callTimeoutMs, DEFAULT_CALL_TIMEOUT_MS);
    this.#estopTimeoutMs = checkTimeout(options.estopTimeoutMs, 2000);
    for (const member of members) this.add(member);
  }

  /** Adds a member; its id must be valid and not taken. */
  add(member: FleetMember): void {
    const id = checkDeviceId(member.id);
    if (this.#members.has(id)) {
      throw new HalError('INVALID_PARAMETER', `the fleet already has a member "${id}"`, {
        details: { device: id },
      });
    }
    this.#members.set(id, { id, hal: member.hal });
  }

  /** Removes a member (its HAL is left as it is). Returns whether it was there. */
  remove(id: string): boolean {
    return this.#members.delete(id);
  }

  /** The members' device ids, in the order they were added. */
  get devices(): string[] {
    return [...this.#members.keys()];
  }

  /** The members, in the order they were added. */
  get members(): FleetMember[] {
    return [...this.#members.values()];
  }

  /** Independent mode: the HAL of one member. An unknown id is INVALID_PARAMETER. */
  hal(id: string): HardwareAbstractionLayer {
    return (selectMembers(this.members, [id])[0] as FleetMember).hal;
  }

  /** Independent mode: one command to one member, with a timeout; never rejects for the call. */
  async independent(
    id: string,
    command: FleetCommand | MemberCall,
    options: { timeoutMs?: number } = {},
  ): Promise<MemberResult> {
    const member = selectMembers(this.members, [id])[0] as FleetMember;
    const report = await this.#run('independent', [member], command, options.timeoutMs);
    return report.results[0] as MemberResult;
  }

  /**
   * Synchronized mode: `command` to every member (or `options.devices`), issued in the same tick,
   * each with its own timeout, every member's own result reported together. While the fleet is
   * e-stopped, everything but a `stop` command is refused for every member without being sent.
   * A malformed command or an unknown device is refused (INVALID_PARAMETER) before anything runs.
   */
  async synchronized(
    command: FleetCommand | MemberCall,
    options: SynchronizedOptions = {},
  ): Promise<FleetReport> {
    const members = selectMembers(this.members, options.devices);
    return this.#run('synchronized', members, command, options.timeoutMs);
  }

  async #run(
    mode: 'independent' | 'synchronized',
    members: FleetMember[],
    command: FleetCommand | MemberCall,
    timeoutMs: number | undefined,
  ): Promise<FleetReport> {
    const call = memberCallOf(command);
    const timeout = checkTimeout(timeoutMs, this.#callTimeoutMs);
    const isStop = typeof command !== 'function' && command.kind === 'stop';
    if (this.#latch.latched && !isStop) {
      const error = new HalError(
        'EMERGENCY_STOPPED',
        'the fleet e-stop is latched; reset it with resetEmergencyStop()',
        { details: { fleet: true } },
      );
      return refuseAll(mode, members, error, this.scheduler);
    }
    return runOnAll(mode, members, call, timeout, this.scheduler);
  }

  /**
   * Starts a leader-follower formation over members of this fleet (one at a time: a running one
   * is stopped first). You drive the leader; `await formation.done` for the report.
   */
  async leaderFollower(options: LeaderFollowerOptions): Promise<LeaderFollower> {
    if (this.#latch.latched) {
      throw new HalError('EMERGENCY_STOPPED', 'the fleet e-stop is latched', {
        details: { fleet: true },
      });
    }
    const formation = new LeaderFollower(this.members, options, this.scheduler, this.#logger);
    if (this.#formation?.running === true) await this.#formation.stop();
    // where the leader starts, before the caller can command it
    await formation.anchor();
    this.#formation = formation.start();
    return formation;
  }

  /** The running formation, if any. */
  get formation(): LeaderFollower | undefined {
    return this.#formation?.running === true ? this.#formation : undefined;
  }

  /** True while the fleet e-stop is latched. Synchronous, never throws. */
  isEmergencyStopped(): boolean {
    return this.#latch.latched;
  }

  /**
   * Latches the fleet and every member at once: each member's `emergencyStop` is issued in the
   * same tick, before anything is awaited, and each gets `estopTimeoutMs` to answer, so a slow
   * or silent member delays only its own entry (TIMEOUT) in the report. A running formation ends.
   */
  async emergencyStop(reason?: string): Promise<FleetReport> {
    this.#latch.latch(sanitizeEstopReason(reason));
    const members = this.members;
    const report = runOnAll(
      'synchronized',
      members,
      (hal) => hal.safety.emergencyStop(reason),
      this.#estopTimeoutMs,
      this.scheduler,
    );
    this.#logger.warn('fleet e-stop', { reason, devices: members.length });
    const formation = this.#formation;
    if (formation?.running === true) void formation.endForEstop('fleet');
    return report;
  }

  /**
   * Resets every member's e-stop (in the same tick) and, when every member succeeded, the fleet's
   * latch. A member that fails keeps the fleet latched; the report says which.
   */
  async resetEmergencyStop(): Promise<FleetReport> {
    const report = await runOnAll(
      'synchronized',
      this.members,
      (hal) => hal.safety.resetEmergencyStop(),
      this.#estopTimeoutMs,
      this.scheduler,
    );
    if (report.success) this.#latch.reset();
    return report;
  }

  /** Stops a running formation and every member's motion (in the same tick). */
  async stop(): Promise<FleetReport> {
    const formation = this.#formation;
    if (formation?.running === true) void formation.stop();
    return runOnAll(
      'synchronized',
      this.members,
      (hal) => hal.locomotion.stop(),
      this.#estopTimeoutMs,
      this.scheduler,
    );
  }
}
