// `hal eval --on emulator`: the cube-emulator this command starts, put into each task's world as
// `hal emulate --camera --world` puts it into a world file: for each trial its camera renders the
// variant's world from where the emulated body truly is (placed at the variant's start, moved by
// the wheels' steps the emulator reports), the trial's PhysicalHAL reads that camera and gives
// poses in the world's frame, and the judge reads the body's true pose from the same wheels.
import type { EvalRobot, StagedRobot, TaskVariant } from '@hal/eval';
import { PhysicalHAL } from '@hal/physical';
import { startEmulatedCamera } from '../emulate/emulated-camera.js';
import type { WheelPositions, WorldPose } from '../emulate/body-pose.js';
import { WHEEL_REPORT_MS } from '../emulate/emulate-options.js';
import { DEFAULT_CONNECT_TIMEOUT_MS } from '../target.js';

/** The wheels of a running emulator, as its `wheels` events tell them. */
export interface EmulatorWheels {
  /** The latest positions, steps from boot. */
  now(): WheelPositions;
  /** Calls `listener` on every report; returns what unsubscribes it. */
  onReport(listener: () => void): () => void;
  /** When the last report came, ms (`performance.now()`). */
  lastReportAt(): number;
}

/** A quiet of this many report periods means the wheels stood still when it began. */
const QUIET_REPORTS = 3;
/** The longest a settle waits, ms. */
const SETTLE_LIMIT_MS = 1000;

/** Resolves once no wheels report has come for a few periods (at most {@link SETTLE_LIMIT_MS}). */
async function settled(wheels: EmulatorWheels): Promise<void> {
  const quietMs = QUIET_REPORTS * WHEEL_REPORT_MS;
  const until = performance.now() + SETTLE_LIMIT_MS;
  for (;;) {
    const wait = wheels.lastReportAt() + quietMs - performance.now();
    if (wait <= 0 || performance.now() >= until) return;
    await new Promise((resolve) => setTimeout(resolve, Math.min(wait, until - performance.now())));
  }
}

/** The emulator at 127.0.0.1:`udpPort`, staged in each trial's world. */
export function stagedEmulator(
  udpPort: number,
  timeScale: number,
  wheels: EmulatorWheels,
): EvalRobot {
  const hal = (cameraUrl?: string, startPose?: WorldPose) =>
    new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-emulator',
        connection: {
          type: 'wifi',
          host: '127.0.0.1',
          udpPort,
          ...(cameraUrl === undefined ? {} : { cameraUrl }),
        },
      },
      {
        timeScale,
        client: 'hal-eval',
        connectTimeoutMs: DEFAULT_CONNECT_TIMEOUT_MS,
        ...(startPose === undefined ? {} : { startPose }),
      },
    );
  return {
    name: 'emulator',
    timeScale,
    open: () => Promise.resolve(hal()),
    stage: async (variant: TaskVariant): Promise<StagedRobot> => {
      await settled(wheels);
      const camera = await startEmulatedCamera({
        host: '127.0.0.1',
        port: 0,
        world: { map: variant.map, objects: variant.objects, start: variant.start },
        wheels: () => wheels.now(),
      });
      return {
        hal: hal(camera.url, variant.start),
        truePose: () => camera.pose(),
        onTruePose: (listener) => wheels.onReport(() => listener(camera.pose())),
        settle: () => settled(wheels),
        close: () => camera.close(),
      };
    },
  };
}
