// A client that knows only the Tafy HAL spec (plain nats.js, the spec's subjects and envelope)
// works against the gateway unchanged; a fleet client uses hal.v1.dev.{device}. Also: the
// `Priority: high` lane, a repeated request id, and bad input.
import { CAPABILITIES, HAL_MAJOR, makeEnvelope } from '@hal/types';
import {
  CapabilityAnnouncementSchema,
  DifferentialStateSchema,
  HalCallReplySchema,
  HealthSchema,
  ImuDataSchema,
  NatsHAL,
  serveHalOnNats,
} from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { connect, headers } from '@nats-io/transport-node';
import type { NatsConnection } from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';
import type { NatsServer } from './nats-server.js';

const json = (value: unknown) => new TextEncoder().encode(JSON.stringify(value));
const parse = (data: Uint8Array) =>
  JSON.parse(new TextDecoder().decode(data)) as {
    device_id: string;
    payload: Record<string, unknown>;
  };
const envelope = (schema: string, payload: unknown) =>
  json({
    ...makeEnvelope({ schema, device_id: 'spec-client' }, payload),
    ts: new Date().toISOString(), // as the spec writes it
  });

let server: NatsServer;
let nc: NatsConnection;
beforeAll(async () => {
  server = await startNatsServer();
  nc = await connect({ servers: server.url });
}, 20_000);
afterAll(async () => {
  await nc.close();
  await stopAllNatsServers();
});

async function served(
  deviceId: string,
  options: { defaultDevice?: boolean; clock?: 'realtime' } = {},
) {
  const hal = new SimulationHAL(options.clock === undefined ? {} : { clock: options.clock });
  await hal.initialize();
  const gateway = await serveHalOnNats(hal, {
    servers: server.url,
    deviceId,
    defaultDevice: options.defaultDevice ?? true,
  });
  return {
    hal,
    close: async () => {
      await gateway.close();
      await hal.cleanup();
    },
  };
}

function first(subject: string, timeoutMs = 5000): Promise<Uint8Array> {
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`nothing on ${subject}`)), timeoutMs);
    const sub = nc.subscribe(subject, {
      callback: (_error, msg) => {
        clearTimeout(timer);
        sub.unsubscribe();
        resolve(msg.data);
      },
    });
  });
}

describe('a spec-only client', () => {
  it(
    'streams IMU and state, drives with motor.differential.cmd and asks for health on the bare subjects',
    { timeout: 20_000 },
    async () => {
      const device = await served('cube-spec');
      try {
        const imu = parse(await first('hal.v1.sensor.imu.data'));
        expect(imu.device_id).toBe('cube-spec');
        expect(ImuDataSchema.parse(imu.payload).source).toBe('simulation');

        const ack = parse(
          (
            await nc.request(
              'hal.v1.motor.differential.cmd',
              envelope('tafylabs/hal/motor/differential/1.0', {
                linear_vel_m_per_s: 0.04,
                angular_vel_rad_per_s: 0,
                duration_ms: 1000,
                stop_action: 'brake',
                unknown_field: 'ignored',
              }),
              { timeout: 5000 },
            )
          ).data,
        );
        expect(ack.payload).toMatchObject({ ok: true });
        const pose = await device.hal.locomotion.getPose();
        expect(pose.position.x).toBeGreaterThan(0.005);

        const state = DifferentialStateSchema.parse(
          parse(await first('hal.v1.motor.differential.state')).payload,
        );
        expect(state.x_m).toBeCloseTo(pose.position.x, 3);

        const health = parse(
          (
            await nc.request(
              'hal.v1.system.health.req',
              envelope('h', { include_diagnostics: true }),
              { timeout: 5000 },
            )
          ).data,
        );
        expect(HealthSchema.parse(health.payload).status).toBe('healthy');

        const caps = parse(
          (await nc.request('hal.v1.system.capability.req', envelope('c', {}), { timeout: 5000 }))
            .data,
        );
        expect(CapabilityAnnouncementSchema.parse(caps.payload).caps).toContain(
          CAPABILITIES.differentialDrive,
        );

        const frame = parse(
          (
            await nc.request('hal.v1.camera.frame.req', envelope('f', { format: 'jpeg' }), {
              timeout: 5000,
            })
          ).data,
        );
        expect(Buffer.from(String(frame.payload['data']), 'base64').subarray(0, 2)).toEqual(
          Buffer.from([0xff, 0xd8]),
        );
      } finally {
        await device.close();
      }
    },
  );

  it(
    'gets the standard error shape for a command beyond the robot, and nothing moves',
    { timeout: 20_000 },
    async () => {
      const device = await served('cube-err');
      try {
        const reply = parse(
          (
            await nc.request(
              'hal.v1.motor.differential.cmd',
              envelope('m', { linear_vel_m_per_s: 10, angular_vel_rad_per_s: 0 }),
              { timeout: 5000 },
            )
          ).data,
        );
        expect(reply.payload['error']).toMatchObject({
          code: 'RANGE_EXCEEDED',
          details: { parameter: 'linear_vel_m_per_s' },
        });
        const malformed = parse(
          (
            await nc.request('hal.v1.motor.differential.cmd', json({ not: 'an envelope' }), {
              timeout: 5000,
            })
          ).data,
        );
        expect(malformed.payload['error']).toMatchObject({ code: 'MALFORMED' });
        expect((await device.hal.locomotion.getPose()).position.x).toBe(0);
      } finally {
        await device.close();
      }
    },
  );
});

describe('fire and forget, e-stop and absence on the spec subjects', () => {
  it(
    'drives on a published command, latches an e-stop published with Priority: high, and resets on request',
    { timeout: 20_000 },
    async () => {
      const device = await served('cube-ff');
      try {
        nc.publish(
          'hal.v1.motor.differential.cmd',
          envelope('m', { linear_vel_m_per_s: 0.04, angular_vel_rad_per_s: 0, duration_ms: 500 }),
        );
        await nc.flush();
        const deadline = Date.now() + 5000;
        while ((await device.hal.locomotion.getPose()).position.x === 0 && Date.now() < deadline) {
          await new Promise((resolve) => setTimeout(resolve, 20));
        }
        expect((await device.hal.locomotion.getPose()).position.x).toBeGreaterThan(0);

        const high = headers();
        high.set('Priority', 'high');
        nc.publish('hal.v1.safety.estop.cmd', envelope('e', { reason: 'spec client' }), {
          headers: high,
        });
        await nc.flush();
        while (!device.hal.safety.isEmergencyStopped() && Date.now() < deadline) {
          await new Promise((resolve) => setTimeout(resolve, 20));
        }
        expect(device.hal.safety.isEmergencyStopped()).toBe(true);
        const refused = parse(
          (
            await nc.request(
              'hal.v1.motor.differential.cmd',
              envelope('m', {
                linear_vel_m_per_s: 0.01,
                angular_vel_rad_per_s: 0,
                duration_ms: 100,
              }),
              { timeout: 5000 },
            )
          ).data,
        );
        expect(refused.payload['error']).toMatchObject({ code: 'EMERGENCY_STOPPED' });
        const reset = parse(
          (await nc.request('hal.v1.safety.estop.reset', envelope('r', {}), { timeout: 5000 }))
            .data,
        );
        expect(reset.payload).toMatchObject({ ok: true, emergency_stopped: false });
        expect(device.hal.safety.isEmergencyStopped()).toBe(false);
      } finally {
        await device.close();
      }
    },
  );

  it(
    'announces capabilities, and answers a camera request NOT_IMPLEMENTED without a camera, streaming no IMU',
    { timeout: 20_000 },
    async () => {
      const hal = new SimulationHAL({
        features: { camera: false, imu: false, rangeSensors: false },
      });
      await hal.initialize();
      const gateway = await serveHalOnNats(hal, {
        servers: server.url,
        deviceId: 'cube-bare',
        defaultDevice: false,
        announceIntervalMs: 100,
      });
      try {
        const imu: string[] = [];
        const sub = nc.subscribe('hal.v1.dev.cube-bare.sensor.>', {
          callback: (_e, msg) => {
            imu.push(msg.subject);
          },
        });
        const announced = CapabilityAnnouncementSchema.parse(
          parse(await first('hal.v1.dev.cube-bare.system.capability.announce')).payload,
        );
        expect(announced.caps).not.toContain(CAPABILITIES.camera);
        expect(announced.caps).not.toContain(CAPABILITIES.imu);
        const frame = parse(
          (
            await nc.request('hal.v1.dev.cube-bare.camera.frame.req', envelope('f', {}), {
              timeout: 5000,
            })
          ).data,
        );
        expect(frame.payload['error']).toMatchObject({ code: 'NOT_IMPLEMENTED' });
        // Several state periods have passed (the announcement and the frame request took a while).
        await first('hal.v1.dev.cube-bare.motor.differential.state');
        await first('hal.v1.dev.cube-bare.motor.differential.state');
        sub.unsubscribe();
        expect(imu).toEqual([]);
      } finally {
        await gateway.close();
        await hal.cleanup();
      }
    },
  );
});

describe('fleet addressing: hal.v1.dev.{device}', () => {
  it(
    'reaches each device on its own subjects, and says who sent each message',
    { timeout: 20_000 },
    async () => {
      const a = await served('cube-a', { defaultDevice: false });
      const b = await served('cube-b', { defaultDevice: false });
      try {
        const senders = new Set<string>();
        await new Promise<void>((resolve, reject) => {
          const timer = setTimeout(() => reject(new Error('not both devices streamed')), 5000);
          const sub = nc.subscribe('hal.v1.dev.*.motor.differential.state', {
            callback: (_e, msg) => {
              senders.add(parse(msg.data).device_id);
              if (senders.size === 2) {
                clearTimeout(timer);
                sub.unsubscribe();
                resolve();
              }
            },
          });
        });
        expect([...senders].sort()).toEqual(['cube-a', 'cube-b']);
        const hal = new NatsHAL({ servers: server.url, deviceId: 'cube-b' });
        await hal.initialize();
        expect((await hal.locomotion.moveForward(2)).success).toBe(true);
        await hal.cleanup();
        expect((await b.hal.locomotion.getPose()).position.x).toBeCloseTo(0.02, 3);
        expect((await a.hal.locomotion.getPose()).position.x).toBe(0);
      } finally {
        await a.close();
        await b.close();
      }
    },
  );
});

describe('priority and repeats', () => {
  it(
    'runs an e-stop with Priority: high at once, ahead of a long move and queued requests',
    { timeout: 30_000 },
    async () => {
      const device = await served('cube-prio', { clock: 'realtime' });
      const call = (request_id: string, name: string, args: unknown[], priority?: 'high') => {
        const h = headers();
        if (priority !== undefined) h.set('Priority', priority);
        return nc
          .request(
            'hal.v1.dev.cube-prio.hal.call.req',
            envelope('call', { request_id, call: name, args }),
            {
              timeout: 20_000,
              headers: h,
            },
          )
          .then((msg) => HalCallReplySchema.parse(parse(msg.data).payload));
      };
      try {
        const finished: string[] = [];
        const long = call('long', 'locomotion.moveForward', [20]).then(
          (r) => (finished.push('long'), r),
        );
        // the long move is under way before the others queue behind it
        await expect
          .poll(async () => (await device.hal.locomotion.getPose()).velocity.linear, {
            timeout: 5000,
          })
          .toBeGreaterThan(0);
        const queued = [1, 2, 3].map((i) =>
          call(`queued-${i}`, 'locomotion.moveForward', [1]).then(
            (r) => (finished.push(`queued-${i}`), r),
          ),
        );
        const started = Date.now();
        const estop = await call('estop', 'safety.emergencyStop', ['test'], 'high');
        finished.push('estop');
        // A 20 cm move takes over 4 s; the e-stop did not wait for it.
        expect(Date.now() - started).toBeLessThan(2000);
        expect(estop.result).toMatchObject({ success: true });
        expect(estop.emergency_stopped).toBe(true);
        const rest = await Promise.all([long, ...queued]);
        expect(finished[0]).toBe('estop');
        expect(rest[0]?.result).toMatchObject({ success: false });
        for (const r of rest.slice(1))
          expect(r.result).toMatchObject({ success: false, code: 'EMERGENCY_STOPPED' });
        expect((await device.hal.locomotion.getPose()).position.x).toBeLessThan(0.05);
      } finally {
        await device.close();
      }
    },
  );

  it(
    'answers a repeated request id from the first execution instead of running it again',
    { timeout: 20_000 },
    async () => {
      const device = await served('cube-repeat');
      try {
        const send = () =>
          nc.request(
            'hal.v1.dev.cube-repeat.hal.call.req',
            envelope('call', { request_id: 'same-id', call: 'locomotion.moveForward', args: [3] }),
            { timeout: 5000 },
          );
        await send();
        await send();
        expect((await device.hal.locomotion.getPose()).position.x).toBeCloseTo(0.03, 3);
        expect(HAL_MAJOR).toBe(1);
      } finally {
        await device.close();
      }
    },
  );
});
