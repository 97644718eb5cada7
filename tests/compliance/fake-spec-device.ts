// A device written only from the Tafy HAL spec, with plain nats.js (no @hal/nats): a kinematic
// point robot that streams state, takes drive commands, answers health and capability queries
// and latches an e-stop. Each fault breaks one thing, so the tests can show that every check
// group of the compliance runner fails a device that gets it wrong.
import type { Msg, NatsConnection, Subscription } from '@nats-io/transport-node';
import jpeg from 'jpeg-js';

/** What the device has beyond drive, e-stop and health (each announced, and served as the spec says). */
export interface Features {
  camera?: boolean;
  imu?: boolean;
  range?: boolean;
}

export interface Faults {
  /** Health replies claim hal_major 2 (message format). */
  badEnvelope?: boolean;
  /** Health replies come this late, ms (timing classes). */
  slowHealthMs?: number;
  /** No state stream at all (timing: the stream rate). */
  noState?: boolean;
  /** Drives at any speed instead of RANGE_EXCEEDED (error handling). */
  acceptsOutOfRange?: boolean;
  /** With acceptsOutOfRange: such a drive goes on this long, ms, whatever its duration_ms. */
  outOfRangeLastsMs?: number;
  /** Announces 50 Hz while streaming at 20 Hz (capability accuracy). */
  announcesWrongRate?: boolean;
  /** Streams IMU data it does not announce (capability accuracy). */
  unannouncedImu?: boolean;
  /** A positive angular velocity turns the pose clockwise, while the state reports it as asked (state consistency). */
  turnsBackwards?: boolean;
  /** The e-stop clears itself on the next drive command (state consistency). */
  estopNotLatched?: boolean;
  /** The state stream never reports the e-stop (state consistency; the runner must still reset). */
  stateHidesEstop?: boolean;
  /** Envelopes carry `ts` as ms since the epoch, not ISO 8601 (message format). */
  numericTs?: boolean;
  /** Camera replies lack width and height (message format). */
  frameWithoutSize?: boolean;
  /** Camera replies state a size that is not the JPEG's (message format). */
  frameWrongSize?: boolean;
  /** Range data in one message for all sensors, `{front_m, left_m, right_m}`, not the spec's (format). */
  rangeAllInOne?: boolean;
  /** IMU data without `orientation_quaternion` (message format). */
  imuWithoutQuaternion?: boolean;
  /** An IMU quaternion that is not of unit length (state consistency). */
  imuNotUnitQuaternion?: boolean;
  /** Health without `free_memory_bytes` and `cpu_percent` (message format). */
  healthWithoutResources?: boolean;
  /** A bare spec payload (no envelope) is refused as MALFORMED (message format). */
  refusesBare?: boolean;
  /** A bare message that is not a valid payload is taken as a stop (error handling). */
  acceptsNeither?: boolean;
}

const TOP_SPEED = 0.05; // m/s
const TOP_TURN = 1; // rad/s
const RATE_HZ = 20;

export interface FakeSpecDevice {
  /** The capabilities it announces. */
  readonly caps: readonly string[];
  readonly estopped: boolean;
  readonly moving: boolean;
  /** Requests received on any of its subjects. */
  readonly requests: number;
  close(): void;
}

export function startFakeSpecDevice(
  nc: NatsConnection,
  deviceId: string,
  faults: Faults = {},
  features: Features = {},
): FakeSpecDevice {
  const caps = ['motor.differential:v1.0', 'safety.estop:v1.0', 'system.health:v1.0'];
  if (features.camera) caps.push('camera.rgb:v1.0');
  if (features.imu) caps.push('sensor.imu:v1.0');
  if (features.range) caps.push('sensor.range:v1.0');
  const frame = jpeg.encode({ data: Buffer.alloc(32 * 24 * 4, 0x60), width: 32, height: 24 }, 80);
  const robot = { x: 0, y: 0, yaw: 0, v: 0, w: 0, until: 0, estopped: false };
  const subs: Subscription[] = [];
  const timers: NodeJS.Timeout[] = [];
  const started = Date.now();
  const at = (domain: string, type: string, action: string) =>
    `hal.v1.dev.${deviceId}.${domain}.${type}.${action}`;
  const envelope = (schema: string, payload: unknown, major = 1) =>
    new TextEncoder().encode(
      JSON.stringify({
        hal_major: major,
        hal_minor: 0,
        schema,
        device_id: deviceId,
        caps,
        ts: faults.numericTs ? Date.now() : new Date().toISOString(),
        payload,
      }),
    );
  const reply = (msg: Msg, schema: string, payload: unknown, major = 1) => {
    if (msg.reply) msg.respond(envelope(schema, payload, major));
  };
  const error = (msg: Msg, code: string, message: string) =>
    reply(msg, 'tafylabs/hal/error/1.0', { error: { code, message } });
  // an envelope's payload, or (as the spec's example driver reads it) a bare payload
  const read = (msg: Msg): Record<string, unknown> | undefined => {
    try {
      const body = JSON.parse(new TextDecoder().decode(msg.data)) as Record<string, unknown>;
      if (typeof body !== 'object' || body === null || Array.isArray(body)) return undefined;
      if (!('hal_major' in body) && !('payload' in body)) {
        if (faults.refusesBare) return undefined;
        if (faults.acceptsNeither && typeof body['linear_vel_m_per_s'] !== 'number') {
          return { linear_vel_m_per_s: 0, angular_vel_rad_per_s: 0 };
        }
        return body;
      }
      return typeof body['payload'] === 'object' && body['payload'] !== null
        ? (body['payload'] as Record<string, unknown>)
        : undefined;
    } catch {
      return undefined;
    }
  };
  let requests = 0;
  const serve = (subject: string, handler: (msg: Msg) => void) =>
    subs.push(
      nc.subscribe(subject, {
        callback: (_e, msg) => {
          requests += 1;
          handler(msg);
        },
      }),
    );
  const announcement = () => ({
    device_type: 'fake-spec-robot',
    mode: 'simulation',
    caps,
    state_rate_hz: faults.announcesWrongRate ? 50 : RATE_HZ,
  });
  const health = () => ({
    status: robot.estopped ? 'emergency_stopped' : 'healthy',
    uptime_s: (Date.now() - started) / 1000,
    mode: 'simulation',
    ...(faults.healthWithoutResources ? {} : { free_memory_bytes: 182_000, cpu_percent: 3.5 }),
  });

  serve(at('motor', 'differential', 'cmd'), (msg) => {
    const cmd = read(msg);
    if (cmd === undefined) return error(msg, 'MALFORMED', 'not a JSON envelope');
    const v = cmd['linear_vel_m_per_s'];
    const w = cmd['angular_vel_rad_per_s'];
    if (typeof v !== 'number' || typeof w !== 'number')
      return error(msg, 'INVALID_PARAMETER', 'velocities must be numbers');
    if (!faults.acceptsOutOfRange && (Math.abs(v) > TOP_SPEED || Math.abs(w) > TOP_TURN)) {
      return error(msg, 'RANGE_EXCEEDED', `top speed ${TOP_SPEED} m/s, ${TOP_TURN} rad/s`);
    }
    if (robot.estopped && (v !== 0 || w !== 0)) {
      if (!faults.estopNotLatched) return error(msg, 'EMERGENCY_STOPPED', 'e-stop latched');
      robot.estopped = false;
    }
    const outOfRange = Math.abs(v) > TOP_SPEED || Math.abs(w) > TOP_TURN;
    const duration =
      outOfRange && faults.outOfRangeLastsMs !== undefined
        ? faults.outOfRangeLastsMs
        : typeof cmd['duration_ms'] === 'number'
          ? cmd['duration_ms']
          : 3000;
    Object.assign(robot, { v, w, until: Date.now() + duration });
    reply(msg, 'tafylabs/hal/ack/1.0', { ok: true });
  });
  serve(at('system', 'health', 'req'), (msg) => {
    if (read(msg) === undefined) return error(msg, 'MALFORMED', 'not a JSON envelope');
    const body = { ...health(), diagnostics: { errors: [] } };
    const send = () =>
      reply(msg, 'tafylabs/hal/system/health/1.0', body, faults.badEnvelope ? 2 : 1);
    if (faults.slowHealthMs !== undefined) setTimeout(send, faults.slowHealthMs);
    else send();
  });
  serve(at('system', 'capability', 'req'), (msg) =>
    reply(msg, 'tafylabs/hal/system/capability/1.0', announcement()),
  );
  serve(at('camera', 'frame', 'req'), (msg) => {
    if (!features.camera) return error(msg, 'NOT_IMPLEMENTED', 'no camera');
    const size = faults.frameWrongSize ? { width: 320, height: 240 } : { width: 32, height: 24 };
    reply(msg, 'tafylabs/hal/camera/frame/1.0', {
      format: 'jpeg',
      ...(faults.frameWithoutSize ? {} : size),
      data: Buffer.from(frame.data).toString('base64'),
      timestamp_ms: Date.now(),
    });
  });
  serve(at('safety', 'estop', 'cmd'), (msg) => {
    Object.assign(robot, { estopped: true, v: 0, w: 0 });
    reply(msg, 'tafylabs/hal/ack/1.0', { ok: true });
  });
  serve(at('safety', 'estop', 'reset'), (msg) => {
    robot.estopped = false;
    reply(msg, 'tafylabs/hal/ack/1.0', { ok: true });
  });

  let last = Date.now();
  /** One period of the device: its motion integrated to `now`, and its streams published. */
  const tick = (now: number): void => {
    if (now >= robot.until) Object.assign(robot, { v: 0, w: 0 });
    const dt = (now - last) / 1000;
    last = now;
    robot.yaw += (faults.turnsBackwards ? -robot.w : robot.w) * dt;
    robot.x += robot.v * Math.cos(robot.yaw) * dt;
    robot.y += robot.v * Math.sin(robot.yaw) * dt;
    if (faults.noState) return;
    nc.publish(
      at('motor', 'differential', 'state'),
      envelope('tafylabs/hal/motor/differential/state/1.0', {
        left_vel_m_per_s: robot.v - robot.w * 0.05,
        right_vel_m_per_s: robot.v + robot.w * 0.05,
        linear_vel_m_per_s: robot.v,
        angular_vel_rad_per_s: robot.w,
        x_m: robot.x,
        y_m: robot.y,
        yaw_rad: robot.yaw,
        emergency_stopped: faults.stateHidesEstop ? false : robot.estopped,
        timestamp_ms: now,
      }),
    );
    if (features.imu) {
      const q = { w: Math.cos(robot.yaw / 2), x: 0, y: 0, z: Math.sin(robot.yaw / 2) };
      nc.publish(
        at('sensor', 'imu', 'data'),
        envelope('tafylabs/hal/sensor/imu/1.0', {
          ...(faults.imuWithoutQuaternion
            ? {}
            : {
                orientation_quaternion: faults.imuNotUnitQuaternion ? { ...q, w: q.w + 0.5 } : q,
              }),
          accel_m_per_s2: { x: 0, y: 0, z: 9.81 },
          gyro_rad_per_s: { x: 0, y: 0, z: robot.w },
        }),
      );
    }
    if (features.range && faults.rangeAllInOne) {
      nc.publish(
        at('sensor', 'range', 'data'),
        envelope('tafylabs/hal/sensor/range/1.0', { front_m: 1, left_m: 1, right_m: 1 }),
      );
    } else if (features.range) {
      for (const sensor of ['front', 'rear']) {
        nc.publish(
          at('sensor', 'range', 'data'),
          envelope('tafylabs/hal/sensor/range/1.0', {
            sensor,
            distance_m: sensor === 'front' ? 0.8 : 4,
            min_range_m: 0.03,
            max_range_m: 4,
            fov_deg: 27,
            confidence: sensor === 'front' ? 0.9 : 0,
          }),
        );
      }
    }
    if (faults.unannouncedImu) {
      nc.publish(
        at('sensor', 'imu', 'data'),
        envelope('tafylabs/hal/sensor/imu/1.0', {
          accel_m_per_s2: { x: 0, y: 0, z: 9.81 },
          gyro_rad_per_s: { x: 0, y: 0, z: robot.w },
          heading_rad: robot.yaw,
          source: 'sensor',
        }),
      );
    }
  };
  // A device keeps its rate on its own CPU. This one shares the test's process, whose timers run
  // late on a loaded machine: the periods it missed are made as soon as it runs again, each at
  // its own time (at most a second of them), so the stream keeps the announced rate on average.
  const periodMs = 1000 / RATE_HZ;
  let due = last;
  timers.push(
    setInterval(() => {
      const now = Date.now();
      due = Math.max(due, now - 1000);
      while (due + periodMs <= now) {
        due += periodMs;
        tick(due);
      }
    }, periodMs / 2),
  );
  nc.publish(
    at('system', 'capability', 'announce'),
    envelope('tafylabs/hal/system/capability/1.0', announcement()),
  );
  timers.push(
    setInterval(
      () =>
        nc.publish(
          at('system', 'capability', 'announce'),
          envelope('tafylabs/hal/system/capability/1.0', announcement()),
        ),
      1000,
    ),
  );
  return {
    caps,
    get estopped() {
      return robot.estopped;
    },
    get moving() {
      return robot.v !== 0 || robot.w !== 0;
    },
    get requests() {
      return requests;
    },
    close: () => {
      for (const timer of timers) clearInterval(timer);
      for (const sub of subs) sub.unsubscribe();
    },
  };
}
