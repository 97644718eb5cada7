import type { HardwareAbstractionLayer } from '@hal/types';
import { jsonSafe } from './json-safe.js';
import { sameSteps } from './link-telemetry.js';
import type { LinkTelemetry } from './link-telemetry.js';
import type { SafetyEvent, WheelSteps } from './messages.js';
import type { McapRecorder } from './recorder.js';
import type { RobotTopicWriter } from './robot-topics.js';

/** What a {@link HalSampler} writes besides the HAL's own reports. */
export interface SamplerSettings {
  posePeriodMs: number;
  linkPeriodMs: number;
  /** The robot's id for the metadata, when not the HAL's own. */
  deviceId?: string | undefined;
  /** The version written into the metadata. */
  version: string;
  /** The map for the metadata (any JSON). */
  map?: unknown;
  /** Stops the sampling when aborted. */
  signal?: AbortSignal | undefined;
}

/** `read()`, or `fallback` when it throws (a HAL that cannot answer now is not a failed recording). */
export function safe<R>(read: () => R, fallback: R): R {
  try {
    return read();
  } catch {
    return fallback;
  }
}

/**
 * What a recording reads from the HAL itself, not through recorded calls: the pose (every
 * `posePeriodMs` once ready), the e-stop latch (a change no safety call made is a trip), the
 * robot's step reports and link statistics, and its metadata record, written once it is ready.
 */
export class HalSampler {
  /** The latch as last seen, by the sampler or by a call. */
  lastLatched: boolean;
  #timer: ReturnType<typeof setInterval> | undefined;
  #linkTimer: ReturnType<typeof setInterval> | undefined;
  #lastSteps: WheelSteps | undefined;
  #sampling = false;
  #robotWritten = false;

  constructor(
    readonly hal: HardwareAbstractionLayer,
    readonly recorder: McapRecorder,
    readonly write: RobotTopicWriter,
    readonly telemetry: LinkTelemetry,
    readonly settings: SamplerSettings,
  ) {
    this.lastLatched = safe(() => hal.safety.isEmergencyStopped(), false);
    settings.signal?.addEventListener('abort', () => this.stopSampling(), { once: true });
  }

  /**
   * The wheel counters the robot last reported, when they are a report not yet taken. Taken as it
   * is read, so each report is written once, at the time it was first read.
   */
  newSteps(): WheelSteps | undefined {
    const steps = safe(() => this.telemetry.steps?.(), undefined);
    if (steps === undefined || sameSteps(this.#lastSteps, steps)) return undefined;
    this.#lastSteps = steps;
    return steps;
  }

  /** Writes the robot's step report, when it is a new one. */
  writeSteps(): void {
    const steps = this.newSteps();
    if (steps !== undefined) this.write.steps(steps);
  }

  /** Writes the link's statistics, when the HAL has them. */
  writeLink = (): void => {
    const link = safe(() => this.telemetry.link?.(), undefined);
    if (link !== undefined) this.write.link(link);
  };

  /** Reads the pose, the latch and the reported steps from the HAL itself (not recorded calls). */
  sample = (): void => {
    this.watchLatch();
    this.writeSteps();
    const { hal, recorder } = this;
    if (this.#sampling || !safe(() => hal.isReady(), false)) return;
    this.#sampling = true;
    const askedAt = recorder.clock();
    try {
      const read = hal.locomotion.getPose().then(
        (pose) => {
          this.#sampling = false;
          this.write.pose(pose, askedAt);
        },
        () => {
          this.#sampling = false;
        },
      );
      // A read still on its way (a remote robot's round trip) as the recording closes is waited
      // for (at most 2 s), so its sample is in the file rather than counted dropped.
      recorder.defer(() => read);
    } catch {
      // a HAL whose getPose throws at once: nothing to sample this time
      this.#sampling = false;
    }
  };

  /** Writes a trip: the latch, read now (or as `latched`), changed with no safety call. */
  watchLatch(latched = safe(() => this.hal.safety.isEmergencyStopped(), this.lastLatched)): void {
    if (latched === this.lastLatched) return;
    this.lastLatched = latched;
    const event: SafetyEvent = {
      event: latched ? 'latched' : 'cleared',
      success: true,
      emergency_stopped: latched,
    };
    this.write.safety(event);
  }

  /** Writes the robot's metadata record (`hal.robot`), once. */
  writeRobot(): void {
    if (this.#robotWritten) return;
    this.#robotWritten = true;
    const { hal, settings } = this;
    const info = safe(() => hal.getDeviceInfo(), undefined);
    this.write.robot({
      device_id: settings.deviceId ?? info?.id ?? '',
      type: info?.type ?? '',
      mode: String(hal.mode),
      capabilities: JSON.stringify(info?.capabilities ?? []),
      robot_config: JSON.stringify(jsonSafe(hal.robotConfig) ?? null),
      // the camera model its frames were taken with (perception projected with it), or null
      camera: JSON.stringify(jsonSafe(info?.camera) ?? null),
      version: settings.version,
      map: JSON.stringify(jsonSafe(settings.map) ?? null),
    });
  }

  /** The HAL is ready: its metadata, then the pose and link timers, and a first sample. */
  onReady(): void {
    this.writeRobot();
    const { posePeriodMs, linkPeriodMs, signal } = this.settings;
    if (posePeriodMs > 0 && this.#timer === undefined && !signal?.aborted) {
      this.#timer = setInterval(this.sample, posePeriodMs);
      (this.#timer as { unref?: () => void }).unref?.();
    }
    if (
      this.telemetry.link &&
      linkPeriodMs > 0 &&
      this.#linkTimer === undefined &&
      !signal?.aborted
    ) {
      this.#linkTimer = setInterval(this.writeLink, linkPeriodMs);
      (this.#linkTimer as { unref?: () => void }).unref?.();
    }
    this.sample();
  }

  /** Stops the pose and link timers (on cleanup, or when the signal aborts). */
  stopSampling(): void {
    if (this.#timer !== undefined) clearInterval(this.#timer);
    if (this.#linkTimer !== undefined) clearInterval(this.#linkTimer);
    this.#timer = undefined;
    this.#linkTimer = undefined;
  }
}
