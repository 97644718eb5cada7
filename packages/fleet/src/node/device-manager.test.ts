import { NatsHAL } from '@hal/nats';
import { SimulationHAL, World } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { createDeviceHAL } from './create-device-hal.js';
import type { DeviceFactories } from './create-device-hal.js';
import { parseFleetConfig } from './device-config.js';
import type { PhysicalDeviceConfig } from './device-config.js';
import { DeviceManager } from './device-manager.js';

/** Builders as a program gives them: simulators in shared worlds; physical devices recorded. */
function factories() {
  const worlds = new Map<string, World>();
  const world = (name = 'default') => {
    if (!worlds.has(name)) worlds.set(name, new World());
    return worlds.get(name)!;
  };
  const physical: PhysicalDeviceConfig[] = [];
  let released = 0;
  const devices: DeviceFactories = {
    simulated: (c) =>
      new SimulationHAL({
        world: world(c.world),
        deviceId: c.id,
        clock: c.clock,
        realtimeSpeed: c.realtimeSpeed,
        ...(c.start === undefined ? {} : { start: c.start }),
      }),
    physical: (c) => {
      physical.push(c);
      return new SimulationHAL({ deviceId: c.id });
    },
    released: () => {
      released += 1;
      for (const w of worlds.values()) w.stopRealtime();
    },
  };
  return { devices, world, physical, released: () => released };
}

const sim = (id: string, y: number) => ({
  type: 'simulated' as const,
  id,
  start: { x: 0, y, yaw: 0 },
  realtimeSpeed: 20,
});

describe('fleet config', () => {
  it('fills defaults and checks every device', () => {
    const config = parseFleetConfig({ devices: [sim('a', 0)] });
    expect(config).toMatchObject({ mode: 'independent', telemetryRateHz: 2, offlineAfterMs: 3000 });
    expect(config.devices[0]).toMatchObject({ world: 'default', clock: 'realtime' });
  });

  it('refuses duplicate ids, a NATS device without servers, an unknown type and bad ids, by path', () => {
    expect(() => parseFleetConfig({ devices: [sim('a', 0), sim('a', 1)] })).toThrow(
      /devices\.1\.id: duplicate id "a"/,
    );
    expect(() => new DeviceManager({ devices: [{ type: 'nats', id: 'n' }] })).toThrow(
      /nats: device "n" is on NATS/,
    );
    expect(() => parseFleetConfig({ devices: [{ type: 'drone', id: 'd' }] })).toThrow(
      /devices\.0\.type/,
    );
    expect(() => parseFleetConfig({ devices: [sim('a b', 0)] })).toThrow(/devices\.0\.id/);
    expect(() => parseFleetConfig({ mode: 'swarm' })).toThrow(/mode/);
    expect(() =>
      parseFleetConfig({ devices: [{ type: 'physical', id: 'p', connection: { type: 'can' } }] }),
    ).toThrow(/connection\.type/);
  });
});

describe('createDeviceHAL routing', () => {
  it('routes simulated and physical devices to the builders given, NATS devices to NatsHAL', () => {
    const built = factories();
    const ctx = { devices: built.devices, nats: { servers: 'nats://127.0.0.1:1' } };
    const s = createDeviceHAL(parseFleetConfig({ devices: [sim('s', 0)] }).devices[0]!, ctx);
    expect(s).toBeInstanceOf(SimulationHAL);
    expect((s as SimulationHAL).world).toBe(built.world('default'));
    const connection = { type: 'wifi' as const, host: '127.0.0.1', udpPort: 4210 };
    const p = createDeviceHAL(
      parseFleetConfig({ devices: [{ type: 'physical', id: 'p', connection }] }).devices[0]!,
      ctx,
    );
    expect(p.getDeviceInfo().id).toBe('p');
    expect(built.physical).toMatchObject([{ id: 'p', connection }]);
    const n = createDeviceHAL({ type: 'nats', id: 'n' }, ctx);
    expect(n).toBeInstanceOf(NatsHAL);
    expect(n.getDeviceInfo().id).toBe('n');
    expect(() => createDeviceHAL({ type: 'nats', id: 'n' }, { devices: built.devices })).toThrow(
      /no NATS servers/,
    );
  });

  it('refuses a simulated or physical device nobody gave a builder for, naming the option', () => {
    const config = parseFleetConfig({
      devices: [
        sim('s', 0),
        { type: 'physical', id: 'p', connection: { type: 'serial', port: '/dev/x' } },
      ],
    });
    expect(() => createDeviceHAL(config.devices[0]!, {})).toThrow(
      /device "s" is simulated: no builder for simulated devices was given \(option "devices.simulated"\)/,
    );
    const onlySimulated: DeviceFactories = { simulated: factories().devices.simulated! };
    expect(() => createDeviceHAL(config.devices[1]!, { devices: onlySimulated })).toThrow(
      /device "p" is physical: no builder/,
    );
    expect(() => new DeviceManager({ devices: [sim('a', 0)] })).toThrow(
      expect.objectContaining({ code: 'INVALID_PARAMETER' }),
    );
  });
});

describe('DeviceManager with simulated devices', () => {
  it('connects every device, reports health and telemetry, and drives them in the fleet modes', async () => {
    const built = factories();
    const manager = new DeviceManager(
      { telemetryRateHz: 10, devices: [sim('a', 0), sim('b', 0.3), sim('c', 0.6)] },
      { devices: built.devices },
    );
    const online: string[] = [];
    manager.on('online', (e) => online.push(e.device));
    try {
      const health = await manager.start();
      expect(health.map((h) => [h.device, h.online, h.ready])).toEqual([
        ['a', true, true],
        ['b', true, true],
        ['c', true, true],
      ]);
      expect(online).toEqual(['a', 'b', 'c']);
      expect(health[1]?.telemetry?.pose.y).toBeCloseTo(0.3, 6);
      // one world for all three
      expect(
        (manager.createDeviceHAL('a') as unknown as { inner: SimulationHAL }).inner.world,
      ).toBe(built.world());
      const report = await manager.fleet.synchronized({ kind: 'moveForward', distanceCm: 2 });
      expect(report.succeeded).toEqual(['a', 'b', 'c']);
      const telemetry = await new Promise<number>((resolve) => {
        const off = manager.on('telemetry', (t) => {
          if (t.device === 'c' && t.pose.x > 0.019) {
            off();
            resolve(t.pose.x);
          }
        });
      });
      expect(telemetry).toBeCloseTo(0.02, 3);
      // the configured speed: the world runs 20x faster than the wall clock
      expect(built.world().realtimeSpeed).toBe(20);
      const estop = await manager.emergencyStop('test');
      expect(estop.success).toBe(true);
      expect(manager.health().every((h) => h.emergencyStopped)).toBe(true);
    } finally {
      await manager.stop();
    }
    // the builders are told once every device is released
    expect(built.released()).toBe(1);
  });

  it('logs a listener that throws and still brings every device online for the others', async () => {
    const errors: Array<Record<string, unknown> | undefined> = [];
    const manager = new DeviceManager(
      { devices: [sim('a', 0), sim('b', 0.3)] },
      {
        devices: factories().devices,
        logger: {
          log: (level, _namespace, _message, fields) => {
            if (level === 'error') errors.push(fields);
          },
        },
      },
    );
    const online: string[] = [];
    manager.on('online', () => {
      throw new Error('broken listener');
    });
    manager.on('online', (e) => online.push(e.device));
    try {
      const health = await manager.start();
      expect(health.map((h) => h.online)).toEqual([true, true]);
      expect(online).toEqual(['a', 'b']);
      expect(errors).toEqual([
        { event: 'online', error: 'broken listener' },
        { event: 'online', error: 'broken listener' },
      ]);
    } finally {
      await manager.stop();
    }
  });

  it('refuses to register a bad or duplicate device and answers an unknown id clearly', () => {
    const manager = new DeviceManager({ devices: [sim('a', 0)] }, { devices: factories().devices });
    expect(() => manager.register(sim('a', 1))).toThrow(/already registered/);
    expect(() => manager.register({ type: 'simulated' })).toThrow(/id/);
    expect(() => manager.register({ type: 'nats', id: 'n' })).toThrow(/no NATS servers/);
    expect(() => manager.createDeviceHAL('zz')).toThrow(/no device "zz" \(devices: a\)/);
    expect(manager.devices).toEqual(['a']);
  });

  it('fails calls to a device that is not online yet with NOT_CONNECTED, offline: true', async () => {
    const manager = new DeviceManager({ devices: [sim('a', 0)] }, { devices: factories().devices });
    const result = await manager.createDeviceHAL('a').locomotion.moveForward(1);
    expect(result).toMatchObject({
      code: 'NOT_CONNECTED',
      details: { device: 'a', offline: true },
    });
    // the e-stop is never refused
    expect((await manager.createDeviceHAL('a').safety.emergencyStop('x')).code).not.toBe(
      'NOT_CONNECTED',
    );
  });

  it("puts every fleet call through wrapDevice, but not the manager's own telemetry reads", async () => {
    const seen: string[] = [];
    /** Notes each call of the HAL's own methods and of its locomotion, by device. */
    const tracing = (device: string, hal: HardwareAbstractionLayer): HardwareAbstractionLayer => {
      const trace = <T extends object>(target: T, prefix: string): T =>
        new Proxy(target, {
          get(obj, prop) {
            const value: unknown = Reflect.get(obj, prop, obj);
            if (prop === 'locomotion' && prefix === '')
              return trace(value as object, 'locomotion.');
            if (typeof value !== 'function') return value;
            return (...args: unknown[]) => {
              seen.push(`${device} ${prefix}${String(prop)}`);
              return (value as (...a: unknown[]) => unknown).apply(obj, args);
            };
          },
        });
      return trace(hal, '');
    };
    const manager = new DeviceManager(
      { telemetryRateHz: 50, devices: [sim('a', 0), sim('b', 0.3)] },
      { devices: factories().devices, wrapDevice: tracing },
    );
    try {
      await manager.start();
      await new Promise((resolve) => setTimeout(resolve, 100)); // several telemetry rounds
      const report = await manager.fleet.synchronized({ kind: 'moveForward', distanceCm: 1 });
      expect(report.succeeded).toEqual(['a', 'b']);
      expect(manager.health().map((h) => h.telemetry !== undefined)).toEqual([true, true]);
    } finally {
      await manager.stop();
    }
    const calls = seen.filter((call) => call.startsWith('a ') && !call.endsWith('isReady'));
    expect(calls).toContain('a initialize');
    expect(calls).toContain('a locomotion.moveForward');
    expect(calls.at(-1)).toBe('a cleanup');
    // 50 Hz telemetry for over 100 ms read the pose many times, none of them through the wrapper
    expect(calls.filter((call) => call === 'a locomotion.getPose').length).toBeLessThan(3);
  });
});
