import { NatsHAL } from '@hal/nats';
import type { NatsConnectionSource } from '@hal/nats';
import { HalError } from '@hal/types';
import type { HardwareAbstractionLayer, Logger } from '@hal/types';
import type { DeviceConfig, PhysicalDeviceConfig, SimulatedDeviceConfig } from './device-config.js';

/**
 * How the HALs of simulated and physical devices are built. The fleet package builds only NATS
 * devices itself: a simulator or a robot's PhysicalHAL (with its serial port's native binding)
 * comes from the program that uses it, so a user of NATS devices installs neither. The `hal`
 * command gives both (`deviceFactories()` of @hal/cli).
 */
export interface DeviceFactories {
  /** A SimulationHAL (or any HAL) for a simulated device; devices naming one `world` share it. */
  simulated?: (config: SimulatedDeviceConfig) => HardwareAbstractionLayer;
  /** A PhysicalHAL (or any HAL) for a physical device. */
  physical?: (config: PhysicalDeviceConfig) => HardwareAbstractionLayer;
  /** Called when the manager has stopped and released every device (stop shared worlds' clocks). */
  released?: () => void;
}

/** What the router needs besides a device's own config. */
export interface DeviceHALContext {
  /** The builders of simulated and physical devices. */
  devices?: DeviceFactories;
  /** How NatsHALs reach NATS (one shared connection, usually). */
  nats?: NatsConnectionSource;
  natsLogger?: Logger;
}

/** INVALID_PARAMETER: a device of a type nobody gave a builder for. */
function noFactory(config: DeviceConfig): HalError {
  return new HalError(
    'INVALID_PARAMETER',
    `device "${config.id}" is ${config.type}: no builder for ${config.type} devices was given (option "devices.${config.type}")`,
    { details: { device: config.id, parameter: `devices.${config.type}` } },
  );
}

/**
 * Routes a device to its HAL: `simulated` and `physical` to the builders of `context.devices`,
 * `nats` to a NatsHAL. The HAL is not initialised. INVALID_PARAMETER when a builder is missing.
 */
export function createDeviceHAL(
  config: DeviceConfig,
  context: DeviceHALContext,
): HardwareAbstractionLayer {
  switch (config.type) {
    case 'simulated': {
      const build = context.devices?.simulated;
      if (build === undefined) throw noFactory(config);
      return build(config);
    }
    case 'physical': {
      const build = context.devices?.physical;
      if (build === undefined) throw noFactory(config);
      return build(config);
    }
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
