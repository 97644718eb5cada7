import { NatsHAL } from '@hal/nats';
import type { NatsConnectionSource } from '@hal/nats';
import { calibrationSource, PhysicalHAL } from '@hal/physical';
import type { World } from '@hal/simulation';
import { SimulationHAL } from '@hal/simulation';
import { HalError, robotConfig } from '@hal/types';
import type { HardwareAbstractionLayer, Logger } from '@hal/types';
import type { DeviceConfig } from './device-config.js';

/** What the router needs besides a device's own config. */
export interface DeviceHALContext {
  /** The world a simulated device named `name` lives in (one per name, shared). */
  world(name: string): World;
  /** How NatsHALs reach NATS (one shared connection, usually). */
  nats?: NatsConnectionSource;
  natsLogger?: Logger;
}

/**
 * Routes a device to its implementation: `simulated` to a SimulationHAL in its named world,
 * `physical` to a PhysicalHAL over UDP or serial, `nats` to a NatsHAL. The HAL is not initialised.
 */
export function createDeviceHAL(
  config: DeviceConfig,
  context: DeviceHALContext,
): HardwareAbstractionLayer {
  switch (config.type) {
    case 'simulated':
      return new SimulationHAL({
        world: context.world(config.world),
        deviceId: config.id,
        clock: config.clock,
        realtimeSpeed: config.realtimeSpeed,
        ...(config.start === undefined ? {} : { start: config.start }),
        ...(config.robot === undefined ? {} : { robot: robotConfig(definedFields(config.robot)) }),
      });
    case 'physical':
      return new PhysicalHAL(
        {
          mode: 'physical',
          deviceId: config.id,
          connection: config.connection,
          ...(config.robot === undefined ? {} : { robot: config.robot }),
        },
        // the robot's calibration file (hal calibrate), sent after every hello
        { calibration: calibrationSource(undefined, process.env) },
      );
    case 'nats': {
      if (context.nats === undefined) {
        throw new HalError(
          'INVALID_PARAMETER',
          `device "${config.id}" is on NATS: no NATS servers given`,
          {
            details: { device: config.id, parameter: 'nats' },
          },
        );
      }
      return new NatsHAL({
        ...context.nats,
        deviceId: config.deviceId ?? config.id,
        ...(config.callTimeoutMs === undefined ? {} : { callTimeoutMs: config.callTimeoutMs }),
        ...(context.natsLogger === undefined ? {} : { logger: context.natsLogger }),
      });
    }
  }
}

/** The fields of `value` that are not undefined (zod's partial output keeps them as keys). */
export function definedFields<T extends object>(
  value: T,
): { [K in keyof T]?: Exclude<T[K], undefined> } {
  return Object.fromEntries(Object.entries(value).filter(([, v]) => v !== undefined)) as {
    [K in keyof T]?: Exclude<T[K], undefined>;
  };
}
