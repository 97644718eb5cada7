// The robot `hal mcp` serves: the embedded simulator, or a PhysicalHAL over UDP or serial.
import { calibrationSource, PhysicalHAL } from '@hal/physical';
import { SimulationHAL, World } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import type { HALConfig, HardwareAbstractionLayer } from '@hal/types';
import type { RobotWorld } from '@hal/mcp';

/** Which robot the server drives: the embedded simulator (default), or one over UDP or serial. */
export interface RobotTarget {
  /** `host` or `host:port` of a robot over WiFi UDP. */
  udp?: string;
  /** Serial device of a robot. */
  serial?: string;
  /** Pre-shared key, hex (protocol 1.1 authentication). */
  key?: string;
  /** Built-in map of the simulator, default `empty`. */
  map?: BuiltinMapName;
}

/** A HAL for the target, not yet initialised, and what is known of its world. */
export function createRobot(
  target: RobotTarget,
  env: Readonly<Record<string, string | undefined>>,
): {
  hal: HardwareAbstractionLayer;
  world: RobotWorld;
} {
  if (target.udp !== undefined && target.serial !== undefined) {
    throw new Error('give --udp or --serial, not both');
  }
  if (target.udp !== undefined || target.serial !== undefined) {
    const key = target.key === undefined ? {} : { key: target.key };
    let connection: NonNullable<HALConfig['connection']>;
    if (target.udp !== undefined) {
      const match = /^(\[[^\]]+\]|[^:]+)(?::(\d+))?$/.exec(target.udp);
      if (match === null) throw new Error(`--udp takes host or host:port, got "${target.udp}"`);
      const host = (match[1] ?? '').replace(/^\[|\]$/g, '');
      connection = {
        type: 'wifi',
        host,
        ...(match[2] === undefined ? {} : { udpPort: Number(match[2]) }),
        ...key,
      };
    } else {
      connection = { type: 'serial', port: target.serial as string, ...key };
    }
    // the robot's calibration file (hal calibrate), sent after every hello
    const calibration = calibrationSource(undefined, env);
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'robot', connection },
      { calibration },
    );
    return { hal, world: {} };
  }
  const sim = new SimulationHAL({
    world: new World(target.map === undefined ? {} : { map: target.map }),
  });
  return { hal: sim, world: { map: () => sim.world.map } };
}
