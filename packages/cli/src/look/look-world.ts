// `hal look --sim --world FILE`: the world of an eval task (map, start, objects, sensors) read
// with @hal/eval's loader (as `hal emulate --camera --world` reads it), and the embedded simulator
// built in it: the robot at the world's start, with the world's sensors.
import { calibratedGeometry } from '@hal/physical';
import { EvalError, loadWorldFile, realiseWorld } from '@hal/eval';
import type { RealisedWorld, TaskWorld } from '@hal/eval';
import { SimulationHAL, World } from '@hal/simulation';
import type { CliIO } from '../io.js';
import type { OpenedHal } from '../target-hal.js';
import { usageError } from '../values.js';

/** A world file, read and made into the simulator's map. */
export interface LookWorld {
  file: string;
  world: TaskWorld;
  realised: RealisedWorld;
}

/**
 * Reads and checks the world file `file`: a USAGE error (exit 2) naming the file and what is
 * wrong with it (the first field that breaks the schema, or why it cannot be read) when it is no
 * world.
 */
export async function readLookWorld(file: string): Promise<LookWorld> {
  try {
    const world = await loadWorldFile(file);
    return { file, world, realised: realiseWorld(world) };
  } catch (error) {
    if (error instanceof EvalError) throw usageError(`"--world" ${error.message}`);
    throw error;
  }
}

/** The embedded simulator in `world`, initialised; `close` lets go of it. */
export async function openWorldSimulator(
  world: LookWorld,
  io: CliIO,
  options: { speed: number; calibration?: string },
): Promise<OpenedHal> {
  const robot =
    options.calibration === undefined
      ? {}
      : { robot: await calibratedGeometry(options.calibration, io.env) };
  const hal = new SimulationHAL({
    ...robot,
    world: new World({ map: world.realised.map }),
    start: world.realised.start,
    features: world.world.sensors,
    clock: 'realtime',
    realtimeSpeed: options.speed,
  });
  await hal.initialize();
  return {
    hal,
    deviceId: hal.getDeviceInfo().id,
    close: () => hal.cleanup().catch(() => undefined),
  };
}
