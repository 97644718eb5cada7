import { scoped, silentLogger } from '@hal/types';
import type { HardwareAbstractionLayer, Logger, Pose } from '@hal/types';
import { errorOf, failureOf, isToolResult, withoutTrailingUndefined } from './call-values.js';
import type { InterceptedCall } from './call-interceptor.js';
import { Fifo } from './fifo.js';
import type { HalSampler } from './hal-sampler.js';
import { safe } from './hal-sampler.js';
import { jsonSafe } from './json-safe.js';
import type { HalCallRecord, SafetyEvent, WheelSteps } from './messages.js';
import type { McapRecorder } from './recorder.js';
import type { RobotTopicWriter } from './robot-topics.js';

/**
 * One recorded call: made as it starts, filled in with what is read the moment it answers, and
 * queued for its record, made later. One object a call, with every field set from the start (one
 * shape): a paced loop's call pays for every allocation on its path.
 */
export interface CallEntry {
  info: InterceptedCall;
  /** The file's clock as the call started and as it answered ({@link McapRecorder.stamp}). */
  start: number | bigint;
  end: number | bigint;
  /** `performance.now()` as it started. */
  startMs: number;
  durationMs: number;
  outcome: HalCallRecord['outcome'];
  value: unknown;
  /** The pose the call left, asked for as it answered (after an action that can move). */
  poseAfter: Promise<Pose> | undefined;
  /** The e-stop latch as it answered. */
  latched: boolean;
  /** The robot's step report as it answered, when it was new (after an action that samples). */
  steps: WheelSteps | undefined;
}

/** The subsystems whose action calls can move the robot: the pose is read after each of them. */
const MOVING_SUBSYSTEMS: ReadonlySet<string> = new Set(['locomotion', 'manipulation', 'safety']);

/** The calls after which the latch, the step report and the pose are sampled. */
function samplesAfter(info: InterceptedCall): boolean {
  if (info.subsystem === 'locomotion') return info.method !== 'getPose';
  if (info.subsystem === 'safety')
    return info.method !== 'isEmergencyStopped' && info.method !== 'getSafetyStatus';
  return false;
}

type CallStatus = { success: boolean; code?: string };

/**
 * The records of a HAL's calls: a call pays on its path only for its times, the latch and (after
 * an action that can move) a pose request; its record, and what follows from it (camera frames,
 * log lines, safety events, a pose sample), is made later, in a moment with no call on its way.
 */
export class CallRecords {
  /** Calls answered whose records wait to be made, oldest first (one deferred task each). */
  readonly #answered = new Fifo<CallEntry>();

  constructor(
    readonly hal: HardwareAbstractionLayer,
    readonly recorder: McapRecorder,
    readonly write: RobotTopicWriter,
    readonly sampler: HalSampler,
    readonly logger: Logger | undefined,
  ) {}

  /** A call starts: its entry, stamped now; the recording's work waits until it answers. */
  started(info: InterceptedCall): CallEntry {
    const { hal, recorder, sampler } = this;
    const start = recorder.stamp();
    const startMs = typeof start === 'number' ? start : performance.now();
    // the link's last figures and steps, read while the link is still open
    if (
      info.method === 'cleanup' &&
      info.subsystem === undefined &&
      safe(() => hal.isReady(), false)
    ) {
      sampler.writeSteps();
      sampler.writeLink();
    }
    // the recording's work waits while the call is on its way, so its reply never waits for it
    recorder.callBegan();
    return {
      info,
      start,
      end: start,
      startMs,
      durationMs: 0,
      outcome: 'returned',
      value: undefined,
      poseAfter: undefined,
      latched: sampler.lastLatched,
      steps: undefined,
    };
  }

  /**
   * What must be read the moment a call answers: its duration, the latch, and after an action
   * that can move the robot, the pose, into `call`. The record itself is made off the call's
   * path (deferred to a moment with no call on its way), so this is all a call pays on its path.
   */
  answered(call: CallEntry, outcome: HalCallRecord['outcome'], value: unknown): void {
    const { hal, recorder, sampler } = this;
    const endMs = performance.now();
    const { info } = call;
    // the file's time it answered: the record, and what it writes beside, are logged at it
    call.end = typeof call.start === 'number' ? endMs : recorder.clock();
    call.durationMs = Math.max(0, endMs - call.startMs);
    call.outcome = outcome;
    call.value = value;
    // The pose this call left is asked for now, before the caller can start another motion.
    try {
      // after a motion, and where the robot stands once ready (the start of the run, for replay)
      const moved = MOVING_SUBSYSTEMS.has(info.subsystem ?? '') && isToolResult(value);
      const ready =
        info.subsystem === undefined && info.method === 'initialize' && outcome === 'resolved';
      if ((moved || ready) && hal.isReady()) {
        const poseAfter = hal.locomotion.getPose();
        poseAfter.catch(() => undefined);
        call.poseAfter = poseAfter;
      }
    } catch {
      // a HAL whose getPose throws at once: no pose after this call
    }
    try {
      call.latched = hal.safety.isEmergencyStopped();
    } catch {
      // a HAL whose latch cannot be read now: taken as unchanged
      call.latched = sampler.lastLatched;
    }
    // a latch this call changed is its own event, never taken for a trip by the sampler meanwhile;
    // a change any other call finds is a trip (rare, so written at once)
    if (info.subsystem === 'safety') sampler.lastLatched = call.latched;
    else sampler.watchLatch(call.latched);
    // The report the motion ended on, taken now: by the time the record is made, the next
    // motion's status replies may have replaced it.
    if (sampler.telemetry.steps !== undefined && samplesAfter(info)) {
      call.steps = sampler.newSteps();
    }
    // one task function for every call (no closure a call): each run takes the oldest call
    this.#answered.push(call);
    recorder.defer(this.#recordNextCall);
    recorder.callEnded(call.durationMs);
  }

  /** Makes the record of the oldest call answered. */
  readonly #recordNextCall = (): Promise<void> | undefined => {
    const call = this.#answered.shift();
    return call === undefined ? undefined : this.#recordNow(call);
  };

  /** Makes a call's record, once the pose it left (if one was asked for) is read. */
  #recordNow(call: CallEntry): Promise<void> | undefined {
    const { recorder, write } = this;
    const { info, outcome, value, poseAfter } = call;
    const at = recorder.timeOf(call.end);
    try {
      const failed = outcome === 'rejected' || outcome === 'threw';
      const status = failed ? { success: false, ...errorOf(value) } : failureOf(value);
      const entry: HalCallRecord = {
        call: info.subsystem ? `${info.subsystem}.${info.method}` : info.method,
        args: (jsonSafe(withoutTrailingUndefined(info.args)) as unknown[] | undefined) ?? [],
        outcome,
        ...status,
        ...(failed || value === undefined ? {} : { result: jsonSafe(value) }),
        start_ns: recorder.timeOf(call.start).toString(),
        duration_ms: call.durationMs,
      };
      if (poseAfter !== undefined) {
        // the pose this call left, read from the HAL itself, goes with the call (for replay)
        return poseAfter.then(
          (pose) => {
            write.pose(pose, at);
            this.#finishCall(call, entry, status, at, pose);
          },
          () => this.#finishCall(call, entry, status, at),
        );
      }
      this.#finishCall(call, entry, status, at);
    } catch (error) {
      scoped(this.logger ?? silentLogger, 'hal:recorder').warn(
        `recorder could not record ${info.method}: ${String(error)}`,
      );
    }
    return undefined;
  }

  /** Writes a call's record, with the pose it left when there is one, and what follows from it. */
  #finishCall(
    call: CallEntry,
    entry: HalCallRecord,
    status: CallStatus,
    at: bigint,
    poseAfter?: Pose,
  ): void {
    this.write.call(
      poseAfter
        ? { ...entry, pose_after: jsonSafe(poseAfter) as HalCallRecord['pose_after'] }
        : entry,
      at,
    );
    this.#afterCall(call, status, at);
  }

  /** What follows from a call, answered as `call` holds, written at `now` (the time it answered). */
  #afterCall(call: CallEntry, status: CallStatus, now: bigint): void {
    const { hal, write, sampler } = this;
    const { info, value } = call;
    const { success: ok, code } = status;
    const name = info.subsystem ? `${info.subsystem}.${info.method}` : info.method;
    if (name === 'initialize' && ok) sampler.onReady();
    if (name === 'cleanup') sampler.stopSampling();
    if (name === 'vision.captureFrame' && ok && typeof value === 'string') write.camera(value, now);
    if (name === 'communication.log') {
      const [message, level] = info.args;
      write.log(
        message,
        level,
        safe(() => hal.getDeviceInfo().id, 'hal'),
        now,
      );
    }
    if (name === 'safety.emergencyStop' || name === 'safety.resetEmergencyStop') {
      const reason = info.args[0];
      const event: SafetyEvent = {
        event: name === 'safety.emergencyStop' ? 'emergency_stop' : 'reset',
        ...(name === 'safety.emergencyStop' && typeof reason === 'string' ? { reason } : {}),
        success: ok,
        ...(code !== undefined ? { code } : {}),
        emergency_stopped: call.latched,
      };
      write.safety(event, now);
    }
    if (samplesAfter(info)) {
      if (call.steps !== undefined) write.steps(call.steps, now);
      sampler.sample();
    }
  }
}
