import { scoped, silentLogger } from '@hal/types';
import type { HardwareAbstractionLayer, Pose } from '@hal/types';
import {
  errorOf,
  failureOf,
  isToolResult,
  period,
  withoutTrailingUndefined,
} from './call-values.js';
import { interceptCalls } from './call-interceptor.js';
import type { CallHooks, InterceptedCall } from './call-interceptor.js';
import { Fifo } from './fifo.js';
import { jsonSafe } from './json-safe.js';
import { linkTelemetry, sameSteps } from './link-telemetry.js';
import type { HalCallRecord, SafetyEvent, WheelSteps } from './messages.js';
import { robotNamespace } from './namespace.js';
import type { RecordHalOptions } from './record-hal-options.js';
import type { McapRecorder } from './recorder.js';
import { robotTopicWriter } from './robot-topics.js';

/** The version written into recordings. */
export const RECORDER_VERSION = '0.1.0';

const SUBSYSTEMS = ['locomotion', 'vision', 'manipulation', 'communication', 'safety'] as const;
/**
 * One recorded call: made as it starts, filled in with what is read the moment it answers, and
 * queued for its record, made later. One object a call, with every field set from the start (one
 * shape): a paced loop's call pays for every allocation on its path.
 */
interface CallEntry {
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

/**
 * Wraps `hal` so that everything passing through it is recorded into `recorder`, and otherwise
 * behaves exactly as `hal` does: the same results, the same errors, synchronous calls still
 * synchronous. Every method of the HAL and of its subsystems is wrapped generically (no list of
 * calls), so a call added to the HAL is recorded with no change here.
 *
 * Recorded: every call (`/hal/calls`), the pose at `posePeriodMs` and after every locomotion,
 * manipulation or safety action (`/hal/pose`, `/tf`, `/hal/pose/raw`), camera frames
 * (`/hal/camera`), log lines (`/hal/log`), e-stops, resets and trips (`/hal/safety`), for a
 * physical robot its reported step counters (`/hal/steps`) and link statistics (`/hal/link`),
 * and the robot's metadata (`hal.robot`) once it is ready. With `namespace`, all of it goes under
 * `/<namespace>` (several robots in one file). A call answers its caller first: only its times,
 * the latch and (after an action that can move) the pose are read at once; the record is made
 * later, in a moment with no call on its way, logged at the time the call answered, and queued,
 * never waiting for the disk.
 */
export function recordHal<T extends HardwareAbstractionLayer>(
  hal: T,
  recorder: McapRecorder,
  options: RecordHalOptions = {},
): T {
  const posePeriodMs = period('posePeriodMs', options.posePeriodMs ?? 100);
  const linkPeriodMs = period('linkPeriodMs', options.linkPeriodMs ?? 1000);
  const space = robotNamespace(options.namespace);
  const telemetry = linkTelemetry(hal);
  // a physical robot's own reports (a HAL without them records neither topic)
  const write = robotTopicWriter(recorder, space, {
    steps: telemetry.steps !== undefined,
    link: telemetry.link !== undefined,
  });

  let timer: ReturnType<typeof setInterval> | undefined;
  let linkTimer: ReturnType<typeof setInterval> | undefined;
  let lastSteps: WheelSteps | undefined;
  let sampling = false;
  let lastLatched = safe(() => hal.safety.isEmergencyStopped(), false);
  let robotWritten = false;

  function safe<R>(read: () => R, fallback: R): R {
    try {
      return read();
    } catch {
      return fallback;
    }
  }

  /**
   * The wheel counters the robot last reported, when they are a report not yet taken. Taken as it
   * is read, so each report is written once, at the time it was first read.
   */
  function newSteps(): WheelSteps | undefined {
    const steps = safe(() => telemetry.steps?.(), undefined);
    if (steps === undefined || sameSteps(lastSteps, steps)) return undefined;
    lastSteps = steps;
    return steps;
  }

  function writeSteps(): void {
    const steps = newSteps();
    if (steps !== undefined) write.steps(steps);
  }

  function writeLink(): void {
    const link = safe(() => telemetry.link?.(), undefined);
    if (link !== undefined) write.link(link);
  }

  /** Reads the pose, the latch and the reported steps from the HAL itself (not recorded calls). */
  function sample(): void {
    watchLatch();
    writeSteps();
    if (sampling || !safe(() => hal.isReady(), false)) return;
    sampling = true;
    const askedAt = recorder.clock();
    try {
      const read = hal.locomotion.getPose().then(
        (pose) => {
          sampling = false;
          write.pose(pose, askedAt);
        },
        () => {
          sampling = false;
        },
      );
      // A read still on its way (a remote robot's round trip) as the recording closes is waited
      // for (at most 2 s), so its sample is in the file rather than counted dropped.
      recorder.defer(() => read);
    } catch {
      // a HAL whose getPose throws at once: nothing to sample this time
      sampling = false;
    }
  }

  /** Writes a trip: the latch, read now (or as `latched`), changed with no safety call. */
  function watchLatch(latched = safe(() => hal.safety.isEmergencyStopped(), lastLatched)): void {
    if (latched === lastLatched) return;
    lastLatched = latched;
    const event: SafetyEvent = {
      event: latched ? 'latched' : 'cleared',
      success: true,
      emergency_stopped: latched,
    };
    write.safety(event);
  }

  function writeRobot(): void {
    if (robotWritten) return;
    robotWritten = true;
    const info = safe(() => hal.getDeviceInfo(), undefined);
    write.robot({
      device_id: options.deviceId ?? info?.id ?? '',
      type: info?.type ?? '',
      mode: String(hal.mode),
      capabilities: JSON.stringify(info?.capabilities ?? []),
      robot_config: JSON.stringify(jsonSafe(hal.robotConfig) ?? null),
      // the camera model its frames were taken with (perception projected with it), or null
      camera: JSON.stringify(jsonSafe(info?.camera) ?? null),
      version: options.version ?? RECORDER_VERSION,
      map: JSON.stringify(jsonSafe(options.map) ?? null),
    });
  }

  function onReady(): void {
    writeRobot();
    if (posePeriodMs > 0 && timer === undefined && !options.signal?.aborted) {
      timer = setInterval(sample, posePeriodMs);
      (timer as { unref?: () => void }).unref?.();
    }
    if (telemetry.link && linkPeriodMs > 0 && linkTimer === undefined && !options.signal?.aborted) {
      linkTimer = setInterval(writeLink, linkPeriodMs);
      (linkTimer as { unref?: () => void }).unref?.();
    }
    sample();
  }

  function stopSampling(): void {
    if (timer !== undefined) clearInterval(timer);
    if (linkTimer !== undefined) clearInterval(linkTimer);
    timer = undefined;
    linkTimer = undefined;
  }
  options.signal?.addEventListener('abort', stopSampling, { once: true });

  /** What follows from a call, answered as `call` holds, written at `now` (the time it answered). */
  function afterCall(
    call: CallEntry,
    status: { success: boolean; code?: string },
    now: bigint,
  ): void {
    const { info, value } = call;
    const { success: ok, code } = status;
    const name = info.subsystem ? `${info.subsystem}.${info.method}` : info.method;
    if (name === 'initialize' && ok) onReady();
    if (name === 'cleanup') stopSampling();
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
      sample();
    }
  }

  /**
   * What must be read the moment a call answers: its duration, the latch, and after an action
   * that can move the robot, the pose, into `call`. The record itself is made off the call's
   * path (deferred to a moment with no call on its way), so this is all a call pays on its path.
   */
  function answered(call: CallEntry, outcome: HalCallRecord['outcome'], value: unknown): void {
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
      call.latched = lastLatched;
    }
    // a latch this call changed is its own event, never taken for a trip by the sampler meanwhile;
    // a change any other call finds is a trip (rare, so written at once)
    if (info.subsystem === 'safety') lastLatched = call.latched;
    else watchLatch(call.latched);
    // The report the motion ended on, taken now: by the time the record is made, the next
    // motion's status replies may have replaced it.
    if (telemetry.steps !== undefined && samplesAfter(info)) call.steps = newSteps();
    // one task function for every call (no closure a call): each run takes the oldest call
    answeredCalls.push(call);
    recorder.defer(recordNextCall);
    recorder.callEnded(call.durationMs);
  }

  /** Calls answered whose records wait to be made, oldest first (one deferred task each). */
  const answeredCalls = new Fifo<CallEntry>();
  function recordNextCall(): Promise<void> | undefined {
    const call = answeredCalls.shift();
    return call === undefined ? undefined : recordNow(call);
  }

  function recordNow(call: CallEntry): Promise<void> | undefined {
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
            finishCall(call, entry, status, at, pose);
          },
          () => finishCall(call, entry, status, at),
        );
      }
      finishCall(call, entry, status, at);
    } catch (error) {
      scoped(options.logger ?? silentLogger, 'hal:recorder').warn(
        `recorder could not record ${info.method}: ${String(error)}`,
      );
    }
    return undefined;
  }

  /** Writes a call's record, with the pose it left when there is one, and what follows from it. */
  function finishCall(
    call: CallEntry,
    entry: HalCallRecord,
    status: { success: boolean; code?: string },
    at: bigint,
    poseAfter?: Pose,
  ): void {
    write.call(
      poseAfter
        ? { ...entry, pose_after: jsonSafe(poseAfter) as HalCallRecord['pose_after'] }
        : entry,
      at,
    );
    afterCall(call, status, at);
  }

  const hooks: CallHooks<CallEntry> = {
    started(info) {
      const start = recorder.stamp();
      const startMs = typeof start === 'number' ? start : performance.now();
      // the link's last figures and steps, read while the link is still open
      if (
        info.method === 'cleanup' &&
        info.subsystem === undefined &&
        safe(() => hal.isReady(), false)
      ) {
        writeSteps();
        writeLink();
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
        latched: lastLatched,
        steps: undefined,
      };
    },
    answered(_info, call, outcome, value) {
      answered(call, outcome, value);
    },
  };

  // a HAL handed over already initialised (as the `hal` command opens its targets)
  if (safe(() => hal.isReady(), false)) onReady();
  return interceptCalls(hal, SUBSYSTEMS, hooks);
}
