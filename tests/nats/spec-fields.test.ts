// The fields and forms of the Tafy HAL spec, as a client written from the spec alone reads them
// off a gateway serving a simulated robot: `ts` in ISO 8601, the camera's size, the one-sensor
// range message, the IMU's quaternion, health's memory and CPU, and bare payloads on commands.
import {
  CameraFrameSchema,
  HealthSchema,
  ImuDataSchema,
  RangeDataSchema,
  RangeSummarySchema,
  serveHalOnNats,
} from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { sanitizeEstopReason } from '@hal/types';
import { connect } from '@nats-io/transport-node';
import type { NatsConnection } from '@nats-io/transport-node';
import jpeg from 'jpeg-js';
import { availableParallelism } from 'node:os';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';

const json = (value: unknown) => new TextEncoder().encode(JSON.stringify(value));
const parse = (data: Uint8Array) =>
  JSON.parse(new TextDecoder().decode(data)) as {
    device_id: string;
    ts: unknown;
    payload: Record<string, unknown>;
  };
const ISO_8601 = /^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(\.\d+)?(Z|[+-]\d\d:\d\d)$/;

let nc: NatsConnection;
let hal: SimulationHAL;
let close: () => Promise<void>;

beforeAll(async () => {
  const server = await startNatsServer();
  nc = await connect({ servers: server.url });
  hal = new SimulationHAL();
  await hal.initialize();
  const gateway = await serveHalOnNats(hal, { servers: server.url, deviceId: 'cube-fields' });
  close = async () => {
    await gateway.close();
    await hal.cleanup();
  };
}, 20_000);

afterAll(async () => {
  await close?.();
  await nc?.close();
  await stopAllNatsServers();
});

/** The messages on `subject` in the next `windowMs`. */
function collect(subject: string, windowMs: number): Promise<Uint8Array[]> {
  const seen: Uint8Array[] = [];
  const sub = nc.subscribe(subject, {
    callback: (_e, msg) => {
      seen.push(msg.data);
    },
  });
  return new Promise((resolve) =>
    setTimeout(() => {
      sub.unsubscribe();
      resolve(seen);
    }, windowMs),
  );
}

const ask = async (subject: string, body: unknown) =>
  parse((await nc.request(subject, json(body), { timeout: 5000 })).data);

describe('the spec fields a gateway sends', () => {
  it('stamps every message with ts in ISO 8601, as the spec writes it', async () => {
    const [state] = await collect('hal.v1.motor.differential.state', 300);
    expect(state).toBeDefined();
    const stamped = parse(state ?? new Uint8Array());
    expect(stamped.ts).toMatch(ISO_8601);
    expect(Math.abs(Date.parse(String(stamped.ts)) - Date.now())).toBeLessThan(60_000);
    const health = await ask('hal.v1.system.health.req', {});
    expect(health.ts).toMatch(ISO_8601);
  });

  it('answers a camera request with the width and height of the JPEG it holds', async () => {
    const frame = CameraFrameSchema.parse((await ask('hal.v1.camera.frame.req', {})).payload);
    const decoded = jpeg.decode(Buffer.from(frame.data, 'base64'));
    expect([frame.width, frame.height]).toEqual([decoded.width, decoded.height]);
    expect([frame.width, frame.height]).toEqual([320, 240]);
  });

  it('publishes one range message per sensor, naming it, beside our all-sensor message', async () => {
    const [perSensor, summaries] = await Promise.all([
      collect('hal.v1.sensor.range.data', 400),
      collect('hal.v1.sensor.range.all', 400),
    ]);
    const messages = perSensor.map((m) => RangeDataSchema.parse(parse(m).payload));
    const names = new Set(messages.map((m) => m.sensor));
    expect([...names].sort()).toEqual(['front', 'front_left', 'front_right', 'left', 'right']);
    for (const m of messages) {
      expect(m.distance_m).toBeGreaterThanOrEqual(m.min_range_m);
      expect(m.distance_m).toBeLessThanOrEqual(m.max_range_m);
      expect(m.fov_deg).toBe(25);
      expect(m.confidence).toBe(m.distance_m < m.max_range_m ? 1 : 0);
    }
    expect(summaries.length).toBeGreaterThan(0);
    const summary = RangeSummarySchema.parse(parse(summaries[0] ?? new Uint8Array()).payload);
    const truth = await hal.vision.getDistanceSensors();
    expect(summary.front_m).toBeCloseTo(truth.front, 2);
  });

  it('streams the IMU orientation as a quaternion of the heading, and no invented readings', async () => {
    await hal.locomotion.rotate('left', 90);
    const [message] = await collect('hal.v1.sensor.imu.data', 300);
    const imu = ImuDataSchema.parse(parse(message ?? new Uint8Array()).payload);
    const q = imu.orientation_quaternion;
    expect(Math.hypot(q.w, q.x, q.y, q.z)).toBeCloseTo(1, 9);
    expect(2 * Math.atan2(q.z, q.w)).toBeCloseTo(imu.heading_rad ?? Number.NaN, 6);
    expect(imu.heading_rad).toBeGreaterThan(1.4);
    // the simulated IMU has no thermometer and no magnetometer: the fields are absent
    expect(imu).not.toHaveProperty('temperature_celsius');
    expect(imu).not.toHaveProperty('mag_tesla');
  });

  it("reports the serving process's free memory and its measured CPU use in health", async () => {
    await ask('hal.v1.system.health.req', {}); // starts a measuring window
    // burn 300 ms of CPU in this process (the gateway's), however long the machine makes it take
    const wallStart = performance.now();
    const cpuStart = process.cpuUsage();
    while ((process.cpuUsage(cpuStart).user + process.cpuUsage(cpuStart).system) / 1000 < 300) {
      Math.sqrt(Math.random());
    }
    const health = HealthSchema.parse((await ask('hal.v1.system.health.req', {})).payload);
    const wallMs = performance.now() - wallStart;
    // at least the 300 ms burnt over the window (a little longer than ours: the first reply came first)
    expect(health.cpu_percent).toBeGreaterThan((300 / (wallMs + 250)) * 100 * 0.8);
    expect(health.cpu_percent).toBeLessThan(100 * availableParallelism() + 10);
    expect(health.free_memory_bytes).toBeGreaterThan(1_000_000);
    expect(health.cpu_percent).toBeGreaterThan(10);
    // no supply voltage is measured on the simulated robot: none is reported
    const detailed = HealthSchema.parse(
      (await ask('hal.v1.system.health.req', { include_diagnostics: true })).payload,
    );
    expect(detailed.diagnostics?.errors).toEqual([]);
    expect(detailed.diagnostics).not.toHaveProperty('voltage');
  });
});

describe('readings the robot measures', () => {
  it('reports the supply voltage in health diagnostics when the robot measures it', async () => {
    const status = hal.safety.getSafetyStatus.bind(hal.safety);
    hal.safety.getSafetyStatus = () => ({ ...status(), batteryVoltage: 7.9 });
    try {
      const health = HealthSchema.parse(
        (await ask('hal.v1.system.health.req', { include_diagnostics: true })).payload,
      );
      expect(health.diagnostics?.voltage).toBe(7.9);
      const [state] = await collect('hal.v1.motor.differential.state', 300);
      expect(parse(state ?? new Uint8Array()).payload['battery_volts']).toBe(7.9);
    } finally {
      hal.safety.getSafetyStatus = status;
    }
  });
});

describe('bare spec payloads on command subjects', () => {
  it('drives on a bare command, as HAL v1 from an unnamed sender', async () => {
    const before = (await hal.locomotion.getPose()).position;
    const ack = await ask('hal.v1.motor.differential.cmd', {
      linear_vel_m_per_s: 0.04,
      angular_vel_rad_per_s: 0,
      duration_ms: 1000,
    });
    expect(ack.payload).toMatchObject({ ok: true });
    const after = (await hal.locomotion.getPose()).position;
    expect(Math.hypot(after.x - before.x, after.y - before.y)).toBeGreaterThan(0.005);
  });

  it('latches an e-stop sent bare and resets it on a bare reset', async () => {
    expect((await ask('hal.v1.safety.estop.cmd', { reason: 'bare' })).payload).toMatchObject({
      ok: true,
    });
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect((await ask('hal.v1.safety.estop.reset', {})).payload).toMatchObject({ ok: true });
    expect(hal.safety.isEmergencyStopped()).toBe(false);
  });

  it('latches an e-stop whatever its reason is, a number included, bare or in an envelope', async () => {
    const envelope = (payload: unknown) => ({
      hal_major: 1,
      hal_minor: 0,
      schema: 's',
      device_id: 'c',
      caps: [],
      ts: new Date().toISOString(),
      payload,
    });
    for (const [body, reason] of [
      [{ reason: 42 }, 42],
      [envelope({ reason: ['pit', 'ahead'] }), ['pit', 'ahead']],
    ] as const) {
      expect((await ask('hal.v1.safety.estop.cmd', body)).payload).toMatchObject({ ok: true });
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe(sanitizeEstopReason(reason));
      expect((await ask('hal.v1.safety.estop.reset', {})).payload).toMatchObject({ ok: true });
    }
    expect(sanitizeEstopReason(42)).toBe('42');
  });

  it('e-stops on a message it cannot read at all, naming why in the reason', async () => {
    const unreadable = [
      new TextEncoder().encode('STOP!'), // not JSON
      json({
        hal_major: 9,
        hal_minor: 0,
        schema: 's',
        device_id: 'c',
        caps: [],
        ts: 0,
        payload: {},
      }),
    ];
    for (const data of unreadable) {
      const ack = parse(
        (await nc.request('hal.v1.safety.estop.cmd', data, { timeout: 5000 })).data,
      );
      expect(ack.payload).toMatchObject({ ok: true, emergency_stopped: true });
      expect(hal.safety.isEmergencyStopped()).toBe(true);
      expect(hal.safety.getSafetyStatus().emergencyStopReason).toMatch(
        /^unreadable e-stop message \([A-Z_]+\)$/,
      );
      expect((await ask('hal.v1.safety.estop.reset', {})).payload).toMatchObject({ ok: true });
    }
  });

  it('refuses what is neither an envelope nor a valid bare payload with MALFORMED, moving nothing', async () => {
    const before = await hal.locomotion.getPose();
    for (const body of [
      { linear_vel_m_per_s: 'fast', angular_vel_rad_per_s: 0 },
      { duration_ms: 500 },
      [0.04, 0],
    ]) {
      const reply = await ask('hal.v1.motor.differential.cmd', body);
      expect(reply.payload['error']).toMatchObject({ code: 'MALFORMED' });
    }
    expect((await hal.locomotion.getPose()).position).toEqual(before.position);
  });
});
