// Real mDNS on this machine (224.0.0.251:5353): a NATS node announced as the spec's
// `_tafynode._tcp`, and found by browsing that service type.
import { randomBytes } from 'node:crypto';
import { afterEach, describe, expect, it } from 'vitest';
import { announceTafyNode, discoverTafyNodes, tafyNodeTxt } from './tafy-node.js';
import type { TafyNodeAnnouncer } from './tafy-node.js';

const uniqueId = (prefix: string) => `${prefix}-${randomBytes(4).toString('hex')}`;
const announcers: TafyNodeAnnouncer[] = [];
afterEach(async () => {
  await Promise.all(announcers.splice(0).map((a) => a.stop()));
});

describe('a Tafy node announcement', () => {
  it('puts device_id and the comma-separated caps in the TXT record, continuing long lists', () => {
    expect(
      tafyNodeTxt({
        deviceId: 'cube-01',
        caps: ['motor.differential:v1.0', 'safety.estop:v1.0'],
        port: 4222,
      }),
    ).toEqual({
      txtvers: '1',
      device_id: 'cube-01',
      caps: 'motor.differential:v1.0,safety.estop:v1.0',
    });
    const many = Array.from({ length: 20 }, (_, i) => `sensor.range${i}:v1.0:fov_deg=25`);
    const txt = tafyNodeTxt({ deviceId: 'cube-01', caps: many, port: 4222 });
    expect(txt['caps1']).toBeDefined();
    const joined = [txt['caps'], txt['caps1'], txt['caps2']].filter(Boolean).join(',').split(',');
    expect(joined).toEqual(many);
    for (const [key, value] of Object.entries(txt)) {
      expect(Buffer.byteLength(`${key}=${value}`)).toBeLessThanOrEqual(255);
    }
  });

  it('refuses a malformed capability, device id or port before anything is sent', async () => {
    expect(() => tafyNodeTxt({ deviceId: 'cube-01', caps: ['motor'], port: 4222 })).toThrow();
    await expect(announceTafyNode({ deviceId: 'cube 01', caps: [], port: 4222 })).rejects.toThrow(
      /"deviceId" is not a device id/,
    );
    await expect(announceTafyNode({ deviceId: 'cube-01', caps: [], port: 0 })).rejects.toThrow(
      /"port" must be 1..65535/,
    );
  });

  it('is found as _tafynode._tcp with its device id, caps, port and NATS servers', async () => {
    const deviceId = uniqueId('gateway');
    const caps = ['locomotion.differential:v1.0', 'safety.estop:v1.0'];
    announcers.push(
      await announceTafyNode({ deviceId, caps, port: 4333, servers: ['nats://127.0.0.1:4333'] }),
    );
    const nodes = await discoverTafyNodes({ timeoutMs: 2500 });
    expect(nodes.find((n) => n.deviceId === deviceId)).toMatchObject({
      deviceId,
      caps,
      port: 4333,
      servers: ['nats://127.0.0.1:4333'],
    });
  });
});
