// From a discovered robot to a PhysicalHAL: the HALConfig that reaches it over UDP.
import { HalError } from '@hal/types';
import type { HALConfig } from '@hal/types';
import { PhysicalHAL } from '@hal/physical';
import type { PhysicalHALOptions } from '@hal/physical';
import type { DiscoveredRobot } from './discover.js';

export interface DiscoveredConnectionOptions {
  /** The robot's pre-shared key, hex. Required when the robot announced `auth=hmac-sha256`. */
  key?: string | undefined;
  /**
   * The address to use instead of the one chosen: by default 127.0.0.1 for a robot announced
   * from this machine, else its first IPv4 address, else its first address.
   */
  address?: string | undefined;
}

/** The address a PhysicalHAL should send to (see {@link DiscoveredConnectionOptions.address}). */
export function addressFor(robot: DiscoveredRobot): string {
  if (robot.onThisMachine) return '127.0.0.1';
  const ipv4 = robot.addresses.find((a) => /^\d+\.\d+\.\d+\.\d+$/.test(a));
  const address = ipv4 ?? robot.addresses[0];
  if (address === undefined) {
    throw new HalError('NOT_CONNECTED', `robot "${robot.deviceId}" announced no address`, {
      details: { deviceId: robot.deviceId },
    });
  }
  return address;
}

/**
 * The PhysicalHAL configuration for a discovered robot: physical mode, its device id, a wifi
 * connection to its address and port, its capabilities, and `key` when given. Throws
 * INVALID_PARAMETER when the robot requires a key and none was given (rather than failing later
 * at `hello`), or when the robot is closed (`auth=unconfigured`: it runs only stop and estop).
 */
export function physicalHalConfigFor(
  robot: DiscoveredRobot,
  options: DiscoveredConnectionOptions = {},
): HALConfig {
  if (robot.auth === 'unconfigured') {
    throw new HalError(
      'INVALID_PARAMETER',
      `robot "${robot.deviceId}" has no key and no opt-out configured: it runs only stop and estop`,
      { details: { deviceId: robot.deviceId, auth: robot.auth } },
    );
  }
  if (robot.requiresKey && options.key === undefined) {
    throw new HalError(
      'INVALID_PARAMETER',
      `robot "${robot.deviceId}" requires its key (auth ${robot.auth}): pass "key"`,
      { details: { deviceId: robot.deviceId, auth: robot.auth } },
    );
  }
  return {
    mode: 'physical',
    deviceId: robot.deviceId,
    capabilities: [...robot.capabilities],
    connection: {
      type: 'wifi',
      host: options.address ?? addressFor(robot),
      udpPort: robot.port,
      ...(options.key === undefined ? {} : { key: options.key }),
    },
  };
}

/** A PhysicalHAL for a discovered robot (not yet initialised: call `initialize()`). */
export function createPhysicalHALFromDiscovery(
  robot: DiscoveredRobot,
  options: DiscoveredConnectionOptions & { hal?: PhysicalHALOptions } = {},
): PhysicalHAL {
  return new PhysicalHAL(physicalHalConfigFor(robot, options), options.hal ?? {});
}
