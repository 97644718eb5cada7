// sensor.imu and sensor.range: streamed at the spec's rate by a device that offers them, and
// not at all by one that does not.
import type { ImuData } from '@hal/nats';
import { angleDifference } from '@hal/types';
import type { RunContext } from '../context.js';
import type { SpecCapability } from '../spec.js';
import type { Received, StreamView } from '../streams.js';
import type { Check } from './check.js';
import { fail, pass } from './check.js';
import { formatVerdict, rateVerdict, watched } from './helpers.js';

function sensorChecks(
  capability: SpecCapability,
  subject: string,
  stream: (ctx: RunContext) => StreamView,
  source?: (message: Received<unknown>) => string | undefined,
): Check[] {
  return [
    {
      capability,
      group: 'timing',
      name: 'stream-rate',
      title: `${subject} streams at 10-100 Hz${source === undefined ? '' : ' per sensor'}`,
      run: (ctx) => rateVerdict(ctx, stream(ctx), subject, source),
    },
    {
      capability,
      group: 'format',
      name: 'stream',
      title: `${subject} messages are valid envelopes from the device with the spec payload`,
      run: async (ctx) => {
        await watched(ctx, stream(ctx));
        return formatVerdict(
          stream(ctx).messages.map((m) => m.inspected),
          `${subject} messages`,
        );
      },
    },
    {
      capability,
      group: 'capability',
      name: 'not-streamed',
      title: `unannounced: nothing is published on ${subject}`,
      when: 'unannounced',
      run: async (ctx) => {
        const collector = stream(ctx);
        await watched(ctx, collector);
        const count = collector.messages.length;
        return count === 0
          ? pass(`nothing in ${ctx.options.streamWindowMs} ms or more`)
          : fail(`${count} message(s) on ${subject}, which the device does not announce`);
      },
    },
  ];
}

/** The sensor a one-sensor range message names (one stream per sensor on one subject). */
function sensorOf(message: Received<unknown>): string | undefined {
  const payload = message.inspected.envelope?.payload;
  if (typeof payload !== 'object' || payload === null) return undefined;
  const sensor = (payload as Record<string, unknown>)['sensor'];
  return typeof sensor === 'string' ? sensor : undefined;
}

/** The yaw of a quaternion (rotation about z, REP-103), radians. */
function yawOf(q: ImuData['orientation_quaternion']): number {
  return Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

const angleBetween = (a: number, b: number) => Math.abs(angleDifference(a, b));

const imuOrientation: Check = {
  capability: 'sensor.imu',
  group: 'state',
  name: 'orientation',
  title:
    'orientation_quaternion is a unit quaternion {w,x,y,z}, and agrees with heading_rad when sent',
  run: async (ctx) => {
    await watched(ctx, ctx.imu);
    const payloads = ctx.imu.messages.flatMap((m) =>
      m.inspected.payload ? [m.inspected.payload] : [],
    );
    if (payloads.length === 0) return fail('no valid IMU message to check');
    for (const imu of payloads) {
      const q = imu.orientation_quaternion;
      const norm = Math.hypot(q.w, q.x, q.y, q.z);
      if (Math.abs(norm - 1) > 1e-3) return fail(`a quaternion of norm ${norm.toFixed(4)}, not 1`);
      if (imu.heading_rad !== undefined && angleBetween(yawOf(q), imu.heading_rad) > 0.01) {
        return fail(
          `the quaternion's yaw is ${yawOf(q).toFixed(3)} rad, heading_rad says ${imu.heading_rad.toFixed(3)}`,
        );
      }
    }
    return pass(`${payloads.length} unit quaternions`);
  },
};

const rangePerSensor: Check = {
  capability: 'sensor.range',
  group: 'state',
  name: 'one-per-sensor',
  title:
    "sensor.range.data is the spec's one-sensor message, each naming its sensor, within its range",
  run: async (ctx) => {
    await watched(ctx, ctx.range);
    const payloads = ctx.range.messages.flatMap((m) =>
      m.inspected.payload ? [m.inspected.payload] : [],
    );
    if (payloads.length === 0) return fail('no valid one-sensor range message to check');
    const limits = new Map<string, string>();
    for (const r of payloads) {
      if (!(r.min_range_m >= 0 && r.min_range_m < r.max_range_m)) {
        return fail(`sensor "${r.sensor}" has the range ${r.min_range_m}..${r.max_range_m} m`);
      }
      if (r.distance_m < r.min_range_m || r.distance_m > r.max_range_m) {
        return fail(
          `sensor "${r.sensor}" read ${r.distance_m} m, outside its ${r.min_range_m}..${r.max_range_m} m`,
        );
      }
      if (!(r.fov_deg > 0 && r.fov_deg <= 360)) {
        return fail(`sensor "${r.sensor}" has a field of view of ${r.fov_deg} degrees`);
      }
      const key = `${r.min_range_m}/${r.max_range_m}/${r.fov_deg}`;
      if ((limits.get(r.sensor) ?? key) !== key) {
        return fail(`sensor "${r.sensor}" changed its range or field of view between messages`);
      }
      limits.set(r.sensor, key);
    }
    return pass(
      `${payloads.length} messages from ${limits.size} sensor(s): ${[...limits.keys()].join(', ')}`,
    );
  },
};

export const SENSOR_CHECKS: readonly Check[] = [
  ...sensorChecks('sensor.imu', 'sensor.imu.data', (ctx) => ctx.imu),
  imuOrientation,
  ...sensorChecks('sensor.range', 'sensor.range.data', (ctx) => ctx.range, sensorOf),
  rangePerSensor,
];
