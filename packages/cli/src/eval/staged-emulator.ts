// `hal eval --on emulator`: the cube-emulator this command starts, put into each task's world as
// `hal emulate --camera --world` puts it into a world file: for each trial its camera renders the
// variant's world from where the emulated body truly is (placed at the variant's start, moved by
// the wheels' steps the emulator reports), the trial's PhysicalHAL reads that camera and gives
// poses in the world's frame, and the judge reads the body's true pose from the same wheels.
import type { EvalRobot, StagedRobot, TaskVariant } from '@hal/eval';
import { PhysicalHAL } from '@hal/physical';
import { delay } from '@hal/types';
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

/** The longest a settle waits, ms. */
const SETTLE_LIMIT_MS = 2000;
/** How often a settle looks again, ms. */
const SETTLE_POLL_MS = 5;

/**
 * Resolves once the wheel reports have caught up with the counters the robot last reported over
 * its link (`reportedSteps`): the two are the same emulator's, told on two channels (its stdout
 * and UDP), so when a motion's result has come back its last wheel report may still be on the
 * way. Without a report over the link yet, once no wheel report has come for a few periods.
 * At most {@link SETTLE_LIMIT_MS}.
 */
async function settled(wheels: EmulatorWheels, hal?: PhysicalHAL): Promise<void> {
  const until = performance.now() + SETTLE_LIMIT_MS;
  const caughtUp = () => {
    const told = hal?.reportedSteps();
    if (told === undefined) return performance.now() - wheels.lastReportAt() >= 3 * WHEEL_REPORT_MS;
    const now = wheels.now();
    return now.left === told.leftSteps && now.right === told.rightSteps;
  };
  while (!caughtUp() && performance.now() < until) await delay(SETTLE_POLL_MS);
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
      const staged = hal(camera.url, variant.start);
      return {
        hal: staged,
        truePose: () => camera.pose(),
        onTruePose: (listener) => wheels.onReport(() => listener(camera.pose())),
        settle: () => settled(wheels, staged),
        close: () => camera.close(),
      };
    },
  };
}
