// A simulated robot facing a wall, for the guard's tests.
import { SimulationHAL, World } from '@hal/simulation';
import type { SimulationHALOptions } from '@hal/simulation';
import type { HardwareAbstractionLayer, Logger } from '@hal/types';

/** The simulated body's footprint radius (its front is this far ahead of its centre), metres. */
export const BODY_RADIUS_M = 0.07;
const WALL_THICKNESS_M = 0.05;

/**
 * A SimulationHAL at the origin facing +x, with a wall across its way whose face is `gapM` ahead
 * of the body's front (no wall when `gapM` is undefined). Options as SimulationHAL's.
 */
export function facingWall(
  gapM: number | undefined,
  options: Omit<SimulationHALOptions, 'world'> = {},
): { sim: SimulationHAL; world: World; gap: () => number } {
  const faceX = BODY_RADIUS_M + (gapM ?? 100);
  const world = new World({
    map: {
      name: 'wall',
      arena: { width: 6, height: 6 },
      walls:
        gapM === undefined
          ? []
          : [{ from: [faceX + WALL_THICKNESS_M / 2, -1], to: [faceX + WALL_THICKNESS_M / 2, 1] }],
    },
  });
  const sim = new SimulationHAL({ world, start: { x: 0, y: 0, yaw: 0 }, ...options });
  // the true distance from the body's front to the wall's face
  const gap = () => faceX - (sim.robot.x + BODY_RADIUS_M);
  return { sim, world, gap };
}

/** A logger that keeps what it is told. */
export function keptLogger(): Logger & { entries: Array<{ level: string; message: string }> } {
  const entries: Array<{ level: string; message: string }> = [];
  return { entries, log: (level, _namespace, message) => entries.push({ level, message }) };
}

/**
 * `hal` with a camera that answers from `hal` until `hang()` is called, then never again (a
 * frame that never comes).
 */
export function hangingCamera(hal: HardwareAbstractionLayer): {
  hal: HardwareAbstractionLayer;
  hang: () => void;
} {
  let hanging = false;
  const vision = hal.vision;
  const wrapped: HardwareAbstractionLayer = {
    get mode() {
      return hal.mode;
    },
    locomotion: hal.locomotion,
    vision: {
      captureFrame: () => (hanging ? new Promise<string>(() => undefined) : vision.captureFrame()),
      scan: (mode) => vision.scan(mode),
      getDistanceSensors: () => vision.getDistanceSensors(),
      getLineSensors: () => vision.getLineSensors(),
      getIMU: () => vision.getIMU(),
    },
    communication: hal.communication,
    safety: hal.safety,
    initialize: () => hal.initialize(),
    cleanup: () => hal.cleanup(),
    isReady: () => hal.isReady(),
    getDeviceInfo: () => hal.getDeviceInfo(),
  };
  return { hal: wrapped, hang: () => (hanging = true) };
}
