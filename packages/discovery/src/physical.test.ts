import { describe, expect, it } from 'vitest';
import { HALConfigSchema } from '@hal/types';
import { PhysicalHAL } from '@hal/physical';
import type { DiscoveredRobot } from './discover.js';
import { addressFor, createPhysicalHALFromDiscovery, physicalHalConfigFor } from './physical.js';

const robot: DiscoveredRobot = {
  deviceId: 'cube-a1b2c3',
  name: 'cube-a1b2c3',
  host: 'cube-a1b2c3.local',
  addresses: ['fe80::1', '192.168.1.40'],
  port: 4210,
  protocolVersion: '1.1',
  auth: 'none',
  requiresKey: false,
  capabilities: ['locomotion.differential:v1.0'],
  onThisMachine: false,
};

describe('physicalHalConfigFor', () => {
  it('reaches a robot on the network at its first IPv4 address and announced port', () => {
    const config = physicalHalConfigFor(robot);
    expect(HALConfigSchema.parse(config)).toEqual({
      mode: 'physical',
      deviceId: 'cube-a1b2c3',
      capabilities: ['locomotion.differential:v1.0'],
      connection: { type: 'wifi', host: '192.168.1.40', udpPort: 4210 },
    });
  });

  it('reaches a robot announced from this machine over loopback', () => {
    expect(addressFor({ ...robot, onThisMachine: true })).toBe('127.0.0.1');
  });

  it('uses the address it is given instead', () => {
    expect(physicalHalConfigFor(robot, { address: '10.0.0.9' }).connection?.host).toBe('10.0.0.9');
  });

  it('passes the key on, and refuses a keyed robot without one', () => {
    const keyed = { ...robot, auth: 'hmac-sha256' as const, requiresKey: true };
    expect(physicalHalConfigFor(keyed, { key: '00ff' }).connection?.key).toBe('00ff');
    expect(() => physicalHalConfigFor(keyed)).toThrow(/requires its key/);
  });

  it('refuses a closed robot and one without an address', () => {
    expect(() =>
      physicalHalConfigFor({ ...robot, auth: 'unconfigured', requiresKey: true }, { key: '00' }),
    ).toThrow(/runs only stop and estop/);
    expect(() => physicalHalConfigFor({ ...robot, addresses: [] })).toThrow(/announced no address/);
  });
});

describe('createPhysicalHALFromDiscovery', () => {
  it('builds an uninitialised PhysicalHAL named by the robot', () => {
    const hal = createPhysicalHALFromDiscovery(robot);
    expect(hal).toBeInstanceOf(PhysicalHAL);
    expect(hal.isReady()).toBe(false);
    expect(hal.getDeviceInfo().id).toBe('cube-a1b2c3');
  });
});
