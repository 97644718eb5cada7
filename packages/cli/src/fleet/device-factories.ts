// The builders of simulated and physical fleet devices the `hal` command gives the device
// manager of @hal/fleet/node (which builds only NATS devices itself).
import type { DeviceFactories } from '@hal/fleet/node';
import { calibrationSource, PhysicalHAL } from '@hal/physical';
import { SimulationHAL, World } from '@hal/simulation';
import { robotConfig } from '@hal/types';

/** The builders, and the worlds their simulated devices share (one per world name). */
export interface FleetDeviceFactories extends Required<DeviceFactories> {
  /** The world `name` (created on first use); simulated devices naming it live in it. */
  world(name?: string): World;
}

/** The fields of `value` that are not undefined (zod's partial output keeps them as keys). */
function definedFields<T extends object>(value: T): { [K in keyof T]?: Exclude<T[K], undefined> } {
  return Object.fromEntries(Object.entries(value).filter(([, v]) => v !== undefined)) as {
    [K in keyof T]?: Exclude<T[K], undefined>;
  };
}

/**
 * SimulationHALs in shared worlds and PhysicalHALs over UDP or serial, each robot sending its
 * calibration file (`hal calibrate`) after every hello. `env` locates the calibration files.
 */
export function deviceFactories(
  env: Readonly<Record<string, string | undefined>> = process.env,
): FleetDeviceFactories {
  const worlds = new Map<string, World>();
  const world = (name = 'default'): World => {
    let found = worlds.get(name);
    if (found === undefined) {
      found = new World();
      worlds.set(name, found);
    }
    return found;
  };
  return {
    world,
    simulated: (config) =>
      new SimulationHAL({
        world: world(config.world),
        deviceId: config.id,
        clock: config.clock,
        realtimeSpeed: config.realtimeSpeed,
        ...(config.start === undefined ? {} : { start: config.start }),
        ...(config.robot === undefined ? {} : { robot: robotConfig(definedFields(config.robot)) }),
      }),
    physical: (config) =>
      new PhysicalHAL(
        {
          mode: 'physical',
          deviceId: config.id,
          connection: config.connection,
          ...(config.robot === undefined ? {} : { robot: config.robot }),
        },
        { calibration: calibrationSource(undefined, env) },
      ),
    released: () => {
      for (const w of worlds.values()) w.stopRealtime();
    },
  };
}
