// sensor.imu and sensor.range: streamed at the spec's rate by a device that offers them, and
// not at all by one that does not.
import type { RunContext } from '../context.js';
import type { SpecCapability } from '../spec.js';
import type { StreamView } from '../streams.js';
import type { Check } from './check.js';
import { fail, pass, sleep } from './check.js';
import { formatVerdict, rateVerdict } from './helpers.js';

function sensorChecks(
  capability: SpecCapability,
  subject: string,
  stream: (ctx: RunContext) => StreamView,
): Check[] {
  return [
    {
      capability,
      group: 'timing',
      name: 'stream-rate',
      title: `${subject} streams at 10-100 Hz`,
      run: (ctx) => rateVerdict(ctx, stream(ctx), subject),
    },
    {
      capability,
      group: 'format',
      name: 'stream',
      title: `${subject} messages are valid envelopes from the device with the spec payload`,
      run: async (ctx) =>
        formatVerdict(
          stream(ctx).messages.map((m) => m.inspected),
          `${subject} messages`,
        ),
    },
    {
      capability,
      group: 'capability',
      name: 'not-streamed',
      title: `unannounced: nothing is published on ${subject}`,
      when: 'unannounced',
      run: async (ctx) => {
        const collector = stream(ctx);
        const waitMs = ctx.options.streamWindowMs - (performance.now() - collector.startedAtMs);
        if (waitMs > 0) await sleep(waitMs);
        const count = collector.messages.length;
        return count === 0
          ? pass(`nothing in ${ctx.options.streamWindowMs} ms or more`)
          : fail(`${count} message(s) on ${subject}, which the device does not announce`);
      },
    },
  ];
}

export const SENSOR_CHECKS: readonly Check[] = [
  ...sensorChecks('sensor.imu', 'sensor.imu.data', (ctx) => ctx.imu),
  ...sensorChecks('sensor.range', 'sensor.range.data', (ctx) => ctx.range),
];
