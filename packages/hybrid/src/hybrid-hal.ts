import {
  failureResult,
  HAL_CALL_TABLE,
  HalBoundary,
  HalError,
  scoped,
  silentLogger,
  toHalError,
  TypedEmitter,
  V1_ROBOT,
} from '@hal/types';
import type {
  CallName,
  CallParams,
  CommunicationInterface,
  DeviceInfo,
  HALMode,
  HALToolResult,
  HardwareAbstractionLayer,
  LocomotionInterface,
  LogLevel,
  PlanarPose,
  Pose,
  RobotConfig,
  SafetyInterface,
  VisionInterface,
} from '@hal/types';
import type { HybridContext } from './context.js';
import {
  composePose,
  DEFAULT_DIVERGENCE_TOLERANCE,
  divergenceBetween,
  planar,
  relativeTo,
} from './divergence.js';
import type { Divergence, DivergenceTolerance } from './divergence.js';
import type { HybridHALOptions } from './options.js';
import { createSafety } from './safety.js';
import { createSubsystems } from './subsystems.js';

/** What a divergence listener is told after a call left the twin beyond its tolerance. */
export interface DivergenceEvent {
  /** The call after which it was measured (`measure` for {@link HybridHAL.measureDivergence}). */
  call: CallName | 'measure';
  divergence: Divergence;
  /** The physical robot's pose, relative to where it stood at `initialize()`. */
  physical: PlanarPose;
  /** The twin's pose, relative to where it stood at `initialize()`. */
  twin: PlanarPose;
}

/** The twin's side of a hybrid result. */
export interface TwinSummary {
  success: boolean;
  code?: HALToolResult['code'];
}

type Side = 'physical' | 'twin';

/** The configuration a HAL validates against, when it exposes one (PhysicalHAL does). */
function exposedConfig(hal: HardwareAbstractionLayer): RobotConfig | undefined {
  const config: unknown = (hal as { robotConfig?: unknown }).robotConfig;
  if (typeof config !== 'object' || config === null) return undefined;
  return typeof (config as { wheelDiameterCm?: unknown }).wheelDiameterCm === 'number'
    ? (config as RobotConfig)
    : undefined;
}

/** A twin whose wheel geometry can be set (SimulationHAL's robot can). */
interface ConfigurableTwin {
  robot: { setConfig(overrides: Partial<RobotConfig>): unknown };
}

function isConfigurable(
  hal: HardwareAbstractionLayer,
): hal is HardwareAbstractionLayer & ConfigurableTwin {
  const robot: unknown = (hal as { robot?: unknown }).robot;
  return (
    typeof robot === 'object' &&
    robot !== null &&
    typeof (robot as { setConfig?: unknown }).setConfig === 'function'
  );
}

/**
 * The physical robot and its simulated twin as one HAL (mode 'hybrid'). Every call is validated
 * and gated once, then runs on both at the same time. The physical result is the truth: it is
 * what the call returns (a twin failure never fails a call), with `data.twin` (the twin's
 * success and code) and `data.divergence` (how far the twin is from the robot after the call).
 */
export class HybridHAL implements HardwareAbstractionLayer {
  readonly mode = 'hybrid' as const;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  /** The physical robot's HAL. */
  readonly physical: HardwareAbstractionLayer;
  /** The simulated twin's HAL. */
  readonly twin: HardwareAbstractionLayer;

  readonly #options: HybridHALOptions;
  readonly #tolerance: DivergenceTolerance;
  readonly #boundary: HalBoundary;
  readonly #config: () => RobotConfig;
  readonly #now: () => number;
  readonly #events = new TypedEmitter<{ divergence: DivergenceEvent }>((_event, thrown) =>
    this.#log('error', 'a divergence listener threw', { error: toHalError(thrown).message }),
  );
  #ready = false;
  #initializing: Promise<void> | undefined;
  #starts: { physical: PlanarPose; twin: PlanarPose } | undefined;
  #latest: Divergence | undefined;

  constructor(options: HybridHALOptions) {
    this.#options = options;
    this.physical = options.physical;
    this.twin = options.twin;
    this.#now = options.now ?? Date.now;
    this.#tolerance = { ...DEFAULT_DIVERGENCE_TOLERANCE, ...options.divergence };
    for (const [name, value] of Object.entries(this.#tolerance)) {
      if (!(Number.isFinite(value) && value >= 0)) {
        throw new HalError('INVALID_PARAMETER', `"${name}" must be a finite number >= 0`, {
          details: { parameter: name, received: value },
        });
      }
    }
    this.#config = options.robotConfig ?? (() => exposedConfig(this.physical) ?? V1_ROBOT);
    this.#boundary = new HalBoundary({
      mode: this.mode,
      config: this.#config,
      isEmergencyStopped: () => this.safety.isEmergencyStopped(),
      isReady: () => this.#ready,
      now: this.#now,
      ...(options.calls === undefined ? {} : { calls: options.calls }),
    });
    const context: HybridContext = {
      physical: this.physical,
      twin: this.twin,
      run: (call, args, onPhysical, onTwin) => this.#run(call, args, onPhysical, onTwin),
      twinPoint: (x, y) => {
        const starts = this.#starts;
        if (starts === undefined) return { x, y };
        const relative = relativeTo(starts.physical, { x, y, yaw: 0 });
        const point = composePose(starts.twin, relative);
        return { x: point.x, y: point.y };
      },
      read: (call, args, body) => this.#boundary.read(call, args, body),
      notify: (call, args, body) => {
        const result = this.#boundary.notify(call, args, body);
        if (!result.success) {
          this.#log('warn', `${call} refused`, { code: result.code, error: result.error });
        }
      },
    };
    const subsystems = createSubsystems(
      context,
      createSafety(context),
      options.calls ?? HAL_CALL_TABLE,
    );
    this.locomotion = subsystems.locomotion;
    this.vision = subsystems.vision;
    this.communication = subsystems.communication;
    this.safety = subsystems.safety;
  }

  /**
   * Initialises both robots at once and anchors the divergence at where each stands. Rejects
   * with the failing side's code and a message that names the side; a side that did come up is
   * cleaned up again.
   */
  async initialize(): Promise<void> {
    if (this.#ready) return;
    this.#initializing ??= this.#open().finally(() => {
      this.#initializing = undefined;
    });
    return this.#initializing;
  }

  async #open(): Promise<void> {
    const [physical, twin] = await Promise.allSettled([
      this.physical.initialize(),
      this.twin.initialize(),
    ]);
    const failures: Array<[Side, unknown]> = [];
    if (physical.status === 'rejected') failures.push(['physical', physical.reason]);
    if (twin.status === 'rejected') failures.push(['twin', twin.reason]);
    if (failures.length > 0) {
      await Promise.allSettled([
        physical.status === 'fulfilled' ? this.physical.cleanup() : undefined,
        twin.status === 'fulfilled' ? this.twin.cleanup() : undefined,
      ]);
      const [side, reason] = failures[0]!;
      const error = toHalError(reason);
      const sides = failures
        .map(
          ([s, r]) =>
            `the ${s === 'physical' ? 'physical robot' : 'twin'} failed to initialise: ${toHalError(r).message}`,
        )
        .join('; ');
      this.#log('error', 'initialize failed', { sides: failures.map(([s]) => s) });
      throw new HalError(error.code, `hybrid: ${sides}`, {
        details: { side, sides: failures.map(([s]) => s) },
        cause: reason,
      });
    }
    if ((this.#options.twinGeometry ?? 'physical') === 'physical') this.#shapeTwin();
    let physicalPose: Pose;
    let twinPose: Pose;
    try {
      [physicalPose, twinPose] = await Promise.all([
        this.physical.locomotion.getPose(),
        this.twin.locomotion.getPose(),
      ]);
    } catch (thrown) {
      await Promise.allSettled([this.physical.cleanup(), this.twin.cleanup()]);
      const error = toHalError(thrown);
      throw new HalError(error.code, `hybrid: could not read the start poses: ${error.message}`, {
        cause: thrown,
      });
    }
    this.#starts = { physical: planar(physicalPose), twin: planar(twinPose) };
    this.#latest = { positionM: 0, yawRad: 0, exceeded: false };
    this.#ready = true;
    this.#log('info', 'initialized', { physical: this.physical.mode, twin: this.twin.mode });
  }

  /**
   * Gives the twin the physical robot's wheel geometry (its calibrated values, once PhysicalHAL
   * has sent them after hello), so both convert distances to steps alike.
   */
  #shapeTwin(): void {
    const physical = exposedConfig(this.physical);
    if (physical === undefined || !isConfigurable(this.twin)) return;
    const { stepsPerRevolution, wheelDiameterCm, wheelBaseCm } = physical;
    this.twin.robot.setConfig({ stepsPerRevolution, wheelDiameterCm, wheelBaseCm });
    this.#log('info', 'twin takes the physical wheel geometry', {
      stepsPerRevolution,
      wheelDiameterCm,
      wheelBaseCm,
    });
  }

  /** Cleans up both robots. Safe to call twice; rejects, naming the side, if either cleanup did. */
  async cleanup(): Promise<void> {
    await this.#initializing?.catch(() => undefined);
    this.#ready = false;
    const results = await Promise.allSettled([this.physical.cleanup(), this.twin.cleanup()]);
    const sides: Side[] = ['physical', 'twin'];
    for (const [index, result] of results.entries()) {
      if (result.status === 'rejected') {
        const error = toHalError(result.reason);
        throw new HalError(
          error.code,
          `hybrid: the ${sides[index]} cleanup failed: ${error.message}`,
          {
            details: { side: sides[index] },
            cause: result.reason,
          },
        );
      }
    }
  }

  /** True while the hybrid HAL is initialised and both robots are ready. */
  /** The limits calls are validated against: the physical robot's (or `options.robotConfig`). */
  get robotConfig(): RobotConfig {
    return this.#config();
  }

  isReady(): boolean {
    return this.#ready && this.physical.isReady() && this.twin.isReady();
  }

  /** The physical robot's identity and capabilities (the truth), in mode 'hybrid'. */
  getDeviceInfo(): DeviceInfo {
    const info = this.physical.getDeviceInfo();
    return {
      id: this.#options.deviceId ?? info.id,
      type: info.type,
      mode: this.mode,
      capabilities: [...info.capabilities],
      ...(info.camera === undefined ? {} : { camera: info.camera }),
    };
  }

  /** The divergence measured after the latest call (zero right after `initialize()`). */
  getDivergence(): Divergence | undefined {
    return this.#latest === undefined ? undefined : { ...this.#latest };
  }

  /** Measures the divergence now (e.g. while a drive without a duration runs). */
  async measureDivergence(): Promise<Divergence | undefined> {
    return this.#measure('measure');
  }

  /**
   * Calls `listener` after every call (or measurement) that leaves the twin beyond the tolerance.
   * Returns a function that removes it. A listener that throws is logged and ignored.
   */
  onDivergence(listener: (event: DivergenceEvent) => void): () => void {
    return this.#events.on('divergence', listener);
  }

  async #run<N extends CallName>(
    call: N,
    args: unknown,
    onPhysical: (params: CallParams<N>) => Promise<HALToolResult>,
    onTwin?: (params: CallParams<N>) => Promise<HALToolResult>,
  ): Promise<HALToolResult> {
    const started = this.#now();
    let params: CallParams<N>;
    try {
      this.#boundary.checkAllowed(call);
      params = this.#boundary.validate(call, args);
    } catch (thrown) {
      const finished = this.#now();
      return failureResult(this.mode, finished, thrown, finished - started);
    }
    const [physical, twin] = await Promise.all([
      this.#settle(this.physical.mode, () => onPhysical(params)),
      onTwin === undefined ? undefined : this.#settle(this.twin.mode, () => onTwin(params)),
    ]);
    if (twin !== undefined && !twin.success) {
      this.#log('warn', `${call}: the twin failed`, { code: twin.code, error: twin.error });
    }
    const divergence = await this.#measure(call);
    const finished = this.#now();
    const data: Record<string, unknown> = { ...physical.data };
    if (twin !== undefined) {
      const summary: TwinSummary = { success: twin.success };
      if (twin.code !== undefined) summary.code = twin.code;
      data['twin'] = summary;
    }
    if (divergence !== undefined) data['divergence'] = divergence;
    const result: HALToolResult = {
      ...physical,
      data,
      mode: this.mode,
      timestamp: finished,
      executionTime: Math.max(0, finished - started),
    };
    return result;
  }

  /** Runs one side's call; anything it throws becomes a failed result (HAL calls should not). */
  async #settle(mode: HALMode, body: () => Promise<HALToolResult>): Promise<HALToolResult> {
    try {
      return await body();
    } catch (thrown) {
      return failureResult(mode, this.#now(), thrown);
    }
  }

  async #measure(call: DivergenceEvent['call']): Promise<Divergence | undefined> {
    const starts = this.#starts;
    if (starts === undefined) return undefined;
    let physical: PlanarPose;
    let twin: PlanarPose;
    try {
      const [p, t] = await Promise.all([
        this.physical.locomotion.getPose(),
        this.twin.locomotion.getPose(),
      ]);
      physical = relativeTo(starts.physical, planar(p));
      twin = relativeTo(starts.twin, planar(t));
    } catch (thrown) {
      this.#log('warn', `${call}: could not read a pose to measure the divergence`, {
        error: toHalError(thrown).message,
      });
      return undefined;
    }
    const divergence = divergenceBetween(physical, twin, this.#tolerance);
    this.#latest = divergence;
    if (divergence.exceeded) {
      this.#log('warn', `${call}: the twin diverged`, { ...divergence });
      this.#events.emit('divergence', { call, divergence: { ...divergence }, physical, twin });
    }
    return { ...divergence };
  }

  #log(level: LogLevel, message: string, fields?: Record<string, unknown>): void {
    scoped(this.#options.logger ?? silentLogger, 'hal:hybrid')[level](message, fields);
  }
}
