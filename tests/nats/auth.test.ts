// An authenticated nats-server (user and password in a config file): the gateway and NatsHAL
// pass the credentials through; without them, or with a wrong password, nothing connects.
import { NatsHAL, serveHalOnNats } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';
import type { NatsServer } from './nats-server.js';

const auth = { user: 'robot-ops', password: 's3cret-pass' };
let server: NatsServer;
beforeAll(async () => {
  server = await startNatsServer({ auth });
}, 20_000);
afterAll(stopAllNatsServers);

describe('an authenticated NATS server', () => {
  it(
    'serves and drives a robot with the right user and password',
    { timeout: 20_000 },
    async () => {
      const device = new SimulationHAL();
      await device.initialize();
      const credentials = { servers: server.url, user: auth.user, pass: auth.password };
      const gateway = await serveHalOnNats(device, { ...credentials, deviceId: 'cube-secure' });
      const hal = new NatsHAL({ ...credentials, deviceId: 'cube-secure' });
      try {
        await hal.initialize();
        expect((await hal.locomotion.moveForward(2)).success).toBe(true);
        expect((await device.locomotion.getPose()).position.x).toBeCloseTo(0.02, 3);
      } finally {
        await hal.cleanup();
        await gateway.close();
        await device.cleanup();
      }
    },
  );

  it(
    'refuses a client without credentials or with a wrong password',
    { timeout: 20_000 },
    async () => {
      await expect(
        new NatsHAL({ servers: server.url, deviceId: 'cube-secure' }).initialize(),
      ).rejects.toThrow(/authori[sz]ation/i);
      await expect(
        new NatsHAL({
          servers: server.url,
          user: auth.user,
          pass: 'wrong',
          deviceId: 'cube-secure',
        }).initialize(),
      ).rejects.toThrow(/authori[sz]ation/i);
    },
  );
});
