// An in-process robot for the bridge's unit tests: a disc in a world of boxes, moved exactly and
// instantly, with range sensors by ray casting, behind the shared HAL boundary. Faults can be
// injected per call. Not exported; the end-to-end tests use SimulationHAL.
import {
  CAPABILITIES,
  EstopLatch,
  HalBoundary,
  HalError,
  motionCall,
  normalizeAngle,
  V1_ROBOT,
} from '@hal/types';
import type {
  CallName,
  CommunicationInterface,
  DeviceInfo,
  DistanceSensors,
  HALToolResult,
  HardwareAbstractionLayer,
  LocomotionInterface,
  Pose,
  SafetyInterface,
  VisionInterface,
} from '@hal/types';

export interface Box {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

export interface FakeHALOptions {
  start?: { x: number; y: number; yaw: number };
  /** Solid boxes; the arena walls are added from `arena`. */
  boxes?: Box[];
  /** Square arena side, metres, centred on the origin. Default 5. */
  arena?: number;
  radius?: number;
  rangeSensors?: boolean;
  maxRange?: number;
}

type Call = { name: string; args: unknown[] };
type Fault = (call: Call) => HALToolResult | 'hang' | 'freeze' | undefined;

export class FakeHAL implements HardwareAbstractionLayer {
  readonly mode = 'simulation' as const;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  /** Every locomotion call, in order. */
  readonly calls: Call[] = [];
  /** Collisions so far. */
  collisions = 0;
  /** Return a result (or 'hang' to never resolve, 'freeze' to succeed without moving). */
  fault: Fault | undefined;
  x: number;
  y: number;
  yaw: number;
  readonly boxes: Box[];
  readonly radius: number;
  #ready = false;
  readonly #estop = new EstopLatch();
  #rangeSensors: boolean;
  readonly #maxRange: number;
  readonly #boundary: HalBoundary;

  constructor(options: FakeHALOptions = {}) {
    const start = options.start ?? { x: 0, y: 0, yaw: 0 };
    this.x = start.x;
    this.y = start.y;
    this.yaw = start.yaw;
    this.radius = options.radius ?? 0.07;
    this.#rangeSensors = options.rangeSensors ?? true;
    this.#maxRange = options.maxRange ?? 2;
    const half = (options.arena ?? 5) / 2;
    this.boxes = [
      ...(options.boxes ?? []),
      { minX: -half - 1, minY: -half - 1, maxX: half + 1, maxY: -half },
      { minX: -half - 1, minY: half, maxX: half + 1, maxY: half + 1 },
      { minX: -half - 1, minY: -half, maxX: -half, maxY: half },
      { minX: half, minY: -half, maxX: half + 1, maxY: half },
    ];
    this.#boundary = new HalBoundary({
      mode: this.mode,
      config: () => V1_ROBOT,
      isEmergencyStopped: () => this.#estop.latched,
      isReady: () => this.#ready,
    });
    const b = this.#boundary;
    const guarded = (
      name: CallName,
      args: unknown[],
      params: Record<string, unknown>,
      body: () => Promise<Record<string, unknown> | void>,
    ): Promise<HALToolResult> => {
      const call = { name, args };
      this.calls.push(call);
      const injected = this.fault?.(call);
      if (injected === 'hang') return new Promise<HALToolResult>(() => undefined);
      if (injected === 'freeze') return b.call(name, params, async () => undefined);
      if (injected !== undefined) return Promise.resolve(injected);
      return b.call(name, params, body);
    };
    // the straight drives are the table's calls whose motion is forward or backward
    const straight = (motion: 'forward' | 'backward') => {
      const { method, name } = motionCall(motion);
      const call = name as CallName;
      const sign = motion === 'forward' ? 1 : -1;
      const run = (distanceCm: number) =>
        guarded(call, [distanceCm], { distanceCm }, async () =>
          this.#drive((sign * distanceCm) / 100),
        );
      return { [method]: run };
    };
    const own = {
      drive: () => Promise.resolve(this.#fail('NOT_IMPLEMENTED', 'drive is not simulated here')),
      moveTo: (x, y, z, speed) =>
        guarded('moveTo', [x, y, z, speed], { x, y, z, speed }, async () => {
          this.yaw = Math.atan2(y - this.y, x - this.x);
          this.#drive(Math.hypot(x - this.x, y - this.y));
        }),
      rotate: (direction, degrees) =>
        guarded('rotate', [direction, degrees], { direction, degrees }, async () => {
          this.yaw = normalizeAngle(
            this.yaw + ((direction === 'left' ? 1 : -1) * degrees * Math.PI) / 180,
          );
        }),
      stop: () => {
        this.calls.push({ name: 'stop', args: [] });
        return b.call('stop', {}, async () => undefined);
      },
      getPose: async (): Promise<Pose> => ({
        position: { x: this.x, y: this.y, z: 0 },
        rotation: { yaw: this.yaw, pitch: 0, roll: 0 },
        velocity: { linear: 0, angular: 0 },
      }),
    } satisfies Partial<LocomotionInterface>;
    this.locomotion = {
      ...straight('forward'),
      ...straight('backward'),
      ...own,
    } as unknown as LocomotionInterface;
    this.vision = {
      captureFrame: async () => 'data:image/jpeg;base64,AAAA',
      scan: () => Promise.reject(new HalError('NOT_IMPLEMENTED', 'no scan')),
      getDistanceSensors: async (): Promise<DistanceSensors> => {
        if (!this.#rangeSensors) throw new HalError('NOT_IMPLEMENTED', 'no range sensors');
        return {
          front: this.cone(this.yaw),
          left: this.cone(this.yaw + Math.PI / 2),
          right: this.cone(this.yaw - Math.PI / 2),
          source: 'simulation',
        };
      },
      getLineSensors: () => Promise.reject(new HalError('NOT_IMPLEMENTED', 'no line sensors')),
      getIMU: () => Promise.reject(new HalError('NOT_IMPLEMENTED', 'no IMU')),
    };
    this.communication = {
      speak: () => Promise.resolve(this.#fail('NOT_IMPLEMENTED', 'no speaker')),
      playSound: () => Promise.resolve(this.#fail('NOT_IMPLEMENTED', 'no speaker')),
      setLED: () => Promise.resolve(this.#fail('NOT_IMPLEMENTED', 'no LED')),
      log: () => undefined,
    };
    this.safety = {
      emergencyStop: async () => {
        this.#estop.latch('emergency stop');
        return { success: true, timestamp: Date.now(), mode: this.mode };
      },
      isEmergencyStopped: () => this.#estop.latched,
      resetEmergencyStop: async () => {
        this.#estop.reset();
        return { success: true, timestamp: Date.now(), mode: this.mode };
      },
      getSafetyStatus: () => ({
        emergencyStopped: this.#estop.latched,
        batteryLevel: 100,
        errors: [],
      }),
    };
  }

  async initialize(): Promise<void> {
    this.#ready = true;
  }

  async cleanup(): Promise<void> {
    this.#ready = false;
  }

  isReady(): boolean {
    return this.#ready;
  }

  getDeviceInfo(): DeviceInfo {
    return {
      id: 'fake-1',
      type: 'fake',
      mode: this.mode,
      capabilities: [CAPABILITIES.emergencyStop],
    };
  }

  /** Latches the emergency stop (as a person pressing the button would). */
  pressEmergencyStop(): void {
    this.#estop.latch('button');
  }

  /** Whether a disc of the robot's radius at (x, y) overlaps a box. */
  touches(x: number, y: number): boolean {
    return this.boxes.some((b) => {
      const nx = Math.min(Math.max(x, b.minX), b.maxX);
      const ny = Math.min(Math.max(y, b.minY), b.maxY);
      return Math.hypot(nx - x, ny - y) < this.radius;
    });
  }

  /** The nearest reading across a 25 degree cone of 5 rays (like the simulated sensors). */
  cone(angle: number): number {
    let nearest = Infinity;
    for (let i = 0; i < 5; i += 1) {
      nearest = Math.min(nearest, this.range(angle + ((i / 4 - 0.5) * 25 * Math.PI) / 180));
    }
    return nearest;
  }

  /** Distance from the body edge to the nearest box along `angle`, capped at the maximum range. */
  range(angle: number): number {
    const step = 0.005;
    for (let d = 0; d <= this.#maxRange + this.radius; d += step) {
      const px = this.x + d * Math.cos(angle);
      const py = this.y + d * Math.sin(angle);
      if (this.boxes.some((b) => px >= b.minX && px <= b.maxX && py >= b.minY && py <= b.maxY)) {
        return Math.max(0, d - this.radius);
      }
    }
    return this.#maxRange;
  }

  #drive(metres: number): void {
    const steps = Math.max(1, Math.ceil(Math.abs(metres) / 0.005));
    const dx = (metres / steps) * Math.cos(this.yaw);
    const dy = (metres / steps) * Math.sin(this.yaw);
    for (let i = 0; i < steps; i += 1) {
      if (this.touches(this.x + dx, this.y + dy)) {
        this.collisions += 1;
        throw new HalError(
          'COLLISION',
          `hit an obstacle at (${this.x.toFixed(2)}, ${this.y.toFixed(2)})`,
        );
      }
      this.x += dx;
      this.y += dy;
    }
  }

  #fail(code: 'NOT_IMPLEMENTED', error: string): HALToolResult {
    return { success: false, code, error, timestamp: Date.now(), mode: this.mode };
  }
}

/** Initialises a fake HAL and answers it, ready to drive. */
export async function ready(hal: FakeHAL): Promise<FakeHAL> {
  await hal.initialize();
  return hal;
}

/** A wall across the middle of the arena with a gap at the top: x in [-0.1, 0.1], y < 1.2. */
export const wall: Box = { minX: -0.1, minY: -2.5, maxX: 0.1, maxY: 1.2 };
/** The same wall as a known map. */
export const wallMap = {
  arena: { width: 5, height: 5 },
  obstacles: [{ kind: 'box' as const, x: 0, y: -0.65, width: 0.2, depth: 3.7 }],
};
