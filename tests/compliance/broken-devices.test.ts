// The compliance runner fails a device that breaks the spec, naming the check: one fault per
// device (a fake spec device written with plain nats.js), so every check group is shown able to
// fail, beside the same fake device without faults passing every check.
import { CHECK_GROUPS, runCompliance } from '@hal/compliance';
import { announceTafyNode } from '@hal/discovery';
import type { CheckGroup, ComplianceReport, SpecCapability } from '@hal/compliance';
import { connect } from '@nats-io/transport-node';
import type { NatsConnection } from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import { startFakeSpecDevice } from './fake-spec-device.js';
import type { FakeSpecDevice, Faults, Features } from './fake-spec-device.js';

let nc: NatsConnection;
let next = 0;

beforeAll(async () => {
  const server = await startNatsServer();
  nc = await connect({ servers: server.url });
}, 30_000);

afterAll(async () => {
  await nc?.close();
  await stopAllNatsServers();
});

/**
 * Every group but timing. A latency or rate measured here is this machine's as much as the fake
 * device's (they share a process, and other test files share the cores), so only the tests of a
 * timing fault run the timing group, and they hold a device to a limit it misses by far.
 */
const NOT_TIMING: CheckGroup[] = CHECK_GROUPS.filter((g) => g !== 'timing');

/** Runs the checks of `capabilities` and `groups` against a fake device with `faults`. */
async function check(
  faults: Faults,
  capabilities?: SpecCapability[],
  features: Features = {},
  groups: readonly CheckGroup[] = NOT_TIMING,
): Promise<{ report: ComplianceReport; device: FakeSpecDevice }> {
  const deviceId = `fake-${(next += 1)}`;
  const device = startFakeSpecDevice(nc, deviceId, faults, features);
  await nc.flush();
  try {
    const report = await runCompliance({
      connection: nc,
      device: deviceId,
      capabilities,
      groups,
      samples: 5,
      streamWindowMs: 1000,
      announceTimeoutMs: 3000,
      motionMs: 2500,
    });
    return { report, device };
  } finally {
    device.close();
  }
}

const failed = (report: ComplianceReport) =>
  report.checks.filter((c) => c.status === 'fail').map((c) => c.id);
const reasonOf = (report: ComplianceReport, id: string) =>
  report.checks.find((c) => c.id === id)?.reason ?? '';
const ALL_FEATURES: Features = { camera: true, imu: true, range: true };

// Concurrent: each test has a device of its own, and most of a run is waiting on its stream.
describe.concurrent('runCompliance against a fake device written from the spec', () => {
  it(
    'passes every check when the device has no fault, including honest absence of what it lacks',
    { timeout: 90_000 },
    async () => {
      const { report, device } = await check({});
      expect(report.checks.filter((c) => c.status === 'fail')).toEqual([]);
      expect(report.ok).toBe(true);
      // camera, IMU and range are not announced: checked to be absent, the rest of theirs skipped
      const absent = report.checks
        .filter((c) => c.status === 'pass' && c.group === 'capability')
        .map((c) => c.id);
      expect(absent).toEqual(
        expect.arrayContaining([
          'camera/capability/not-implemented',
          'sensor.imu/capability/not-streamed',
          'sensor.range/capability/not-streamed',
        ]),
      );
      const skipped = report.checks.filter((c) => c.status === 'skip');
      expect(skipped.length).toBeGreaterThan(0);
      for (const skip of skipped)
        expect(skip.reason).toContain(`does not announce ${skip.capability}`);
      expect(device.estopped).toBe(false);
      expect(device.moving).toBe(false);
    },
  );

  it(
    'passes every check of a device with a camera, an IMU and range sensors that follows the spec',
    { timeout: 90_000 },
    async () => {
      const { report } = await check({}, ['camera', 'sensor.imu', 'sensor.range'], ALL_FEATURES);
      expect(report.checks.filter((c) => c.status !== 'pass')).toEqual([]);
      expect(report.checks.map((c) => c.id)).toEqual(
        expect.arrayContaining([
          'camera/format/frame-reply',
          'sensor.imu/state/orientation',
          'sensor.range/state/one-per-sensor',
        ]),
      );
    },
  );

  it(
    'measures every timing check of a device with all capabilities, on `samples` requests each',
    { timeout: 90_000 },
    async () => {
      const capabilities: SpecCapability[] = ['system', 'motor.differential', 'safety', 'camera'];
      const { report } = await check({}, capabilities, ALL_FEATURES, ['timing']);
      expect(report.groups).toEqual(['timing']);
      expect(new Set(report.checks.map((c) => c.group))).toEqual(new Set(['timing']));
      expect(report.checks.map((c) => c.id)).toEqual(
        expect.arrayContaining([
          'system/timing/health',
          'motor.differential/timing/stop-command',
          'motor.differential/timing/state-rate',
          'camera/timing/frame',
        ]),
      );
      for (const c of report.checks) {
        // pass or fail is this machine's to say: what must hold is that each was measured
        expect(c.status, c.id).not.toBe('skip');
        if (c.rateHz !== undefined) expect(c.rateHz, c.id).toBeGreaterThan(0);
        else {
          expect(c.measured?.samples, c.id).toBe(5);
          expect(c.latencyClass, c.id).toBeDefined();
        }
      }
    },
  );

  it(
    'runs only the check groups asked for, and refuses an unknown group before sending anything',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({}, ['motor.differential'], {}, ['errors', 'format']);
      expect(report.groups).toEqual(['format', 'errors']);
      expect(report.checks.length).toBeGreaterThan(3);
      expect(new Set(report.checks.map((c) => c.group))).toEqual(new Set(['format', 'errors']));
      const device = startFakeSpecDevice(nc, 'fake-groups');
      try {
        const run = runCompliance({
          connection: nc,
          device: 'fake-groups',
          groups: ['timing', 'speed' as CheckGroup],
        });
        await expect(run).rejects.toMatchObject({
          code: 'INVALID_PARAMETER',
          message: '"groups" must be among format, timing, errors, capability, state, got "speed"',
        });
        await expect(
          runCompliance({ connection: nc, device: 'fake-groups', groups: [] }),
        ).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
        expect(device.requests).toBe(0);
      } finally {
        device.close();
      }
    },
  );

  it(
    'fails message format when a reply carries the wrong hal_major',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ badEnvelope: true }, ['system']);
      expect(failed(report)).toContain('system/format/health-reply');
      const check_ = report.checks.find((c) => c.id === 'system/format/health-reply');
      expect(check_?.reason).toContain('hal_major is 2');
    },
  );

  it(
    'fails the interactive timing class when health replies take 150 ms',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ slowHealthMs: 150 }, ['system'], {}, CHECK_GROUPS);
      expect(failed(report)).toContain('system/timing/health');
      const health = report.checks.find((c) => c.id === 'system/timing/health');
      expect(health?.measured?.p50Ms).toBeGreaterThanOrEqual(150);
    },
  );

  it(
    'fails the stream rate (and the state checks) when the device never streams state',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ noState: true }, ['motor.differential'], {}, CHECK_GROUPS);
      expect(failed(report)).toEqual(
        expect.arrayContaining([
          'motor.differential/timing/state-rate',
          'motor.differential/state/drive-forward',
          'motor.differential/format/state-stream',
        ]),
      );
    },
  );

  it(
    'fails error handling when an out-of-range velocity is accepted, and says it moved',
    { timeout: 60_000 },
    async () => {
      const { report, device } = await check({ acceptsOutOfRange: true }, ['motor.differential']);
      expect(failed(report)).toEqual(['motor.differential/errors/out-of-range']);
      expect(
        report.checks.find((c) => c.id === 'motor.differential/errors/out-of-range')?.reason,
      ).toContain('expected error RANGE_EXCEEDED, got a success reply');
      expect(device.moving).toBe(false); // stopped on the way out
    },
  );

  it(
    'stops a robot a failed check left moving, so that the next checks do not fail for it',
    { timeout: 60_000 },
    async () => {
      // the accepted out-of-range drive goes on for 4 s: without a stop, every later check
      // that requires nothing to change would see it
      const { report, device } = await check({ acceptsOutOfRange: true, outOfRangeLastsMs: 4000 }, [
        'motor.differential',
      ]);
      expect(failed(report)).toEqual(['motor.differential/errors/out-of-range']);
      expect(device.moving).toBe(false);
    },
  );

  it(
    'fails capability accuracy when the announced state rate is not the streamed one',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ announcesWrongRate: true }, ['motor.differential']);
      expect(failed(report)).toEqual(['motor.differential/capability/announced-rate']);
    },
  );

  it(
    'fails capability accuracy when the device streams IMU data it does not announce',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ unannouncedImu: true }, ['sensor.imu']);
      expect(failed(report)).toEqual(['sensor.imu/capability/not-streamed']);
    },
  );

  it(
    'fails state consistency when a positive angular velocity turns the robot clockwise',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ turnsBackwards: true }, ['motor.differential']);
      expect(failed(report)).toEqual(['motor.differential/state/turn-left']);
      expect(
        report.checks.find((c) => c.id === 'motor.differential/state/turn-left')?.reason,
      ).toMatch(/turned -0\.\d+ rad/);
    },
  );

  it(
    'fails state consistency when the e-stop clears itself on the next command',
    { timeout: 60_000 },
    async () => {
      const { report, device } = await check({ estopNotLatched: true }, ['safety']);
      expect(failed(report)).toEqual(['safety/state/estop-latches']);
      expect(device.estopped).toBe(false);
    },
  );

  it(
    'resets its own e-stop even when the e-stop check fails half-way',
    { timeout: 60_000 },
    async () => {
      const { report, device } = await check({ stateHidesEstop: true }, ['safety']);
      expect(failed(report)).toEqual(['safety/state/estop-latches']);
      expect(report.checks.find((c) => c.id === 'safety/state/estop-latches')?.reason).toContain(
        'never showed emergency_stopped',
      );
      expect(device.estopped).toBe(false);
    },
  );

  it(
    'fails message format when ts is a number of milliseconds, not ISO 8601',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ numericTs: true }, ['system']);
      expect(failed(report)).toContain('system/format/health-reply');
      expect(reasonOf(report, 'system/format/health-reply')).toContain('not an ISO 8601 string');
    },
  );

  it(
    'fails message format when health lacks free_memory_bytes and cpu_percent',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ healthWithoutResources: true }, ['system']);
      expect(failed(report)).toContain('system/format/health-reply');
      expect(reasonOf(report, 'system/format/health-reply')).toContain('free_memory_bytes');
    },
  );

  it(
    'fails message format when a bare spec payload is refused on a command subject',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ refusesBare: true }, ['system', 'motor.differential']);
      expect(failed(report)).toEqual([
        'system/format/bare-request',
        'motor.differential/format/bare-command',
      ]);
    },
  );

  it(
    'fails error handling when a bare message that is no valid payload is taken as a command',
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ acceptsNeither: true }, ['motor.differential']);
      expect(failed(report)).toEqual(['motor.differential/errors/neither-envelope-nor-payload']);
    },
  );

  it(
    'fails message format when a camera reply lacks its width and height, or states the wrong ones',
    { timeout: 60_000 },
    async () => {
      const without = await check({ frameWithoutSize: true }, ['camera'], ALL_FEATURES);
      expect(failed(without.report)).toContain('camera/format/frame-reply');
      expect(reasonOf(without.report, 'camera/format/frame-reply')).toMatch(/width/);
      const wrong = await check({ frameWrongSize: true }, ['camera'], ALL_FEATURES);
      expect(failed(wrong.report)).toEqual(['camera/format/frame-reply']);
      expect(reasonOf(wrong.report, 'camera/format/frame-reply')).toContain(
        'says 320x240, the JPEG is 32x24',
      );
    },
  );

  it(
    "fails message format when range data is one message for all sensors, not the spec's one-sensor form",
    { timeout: 60_000 },
    async () => {
      const { report } = await check({ rangeAllInOne: true }, ['sensor.range'], ALL_FEATURES);
      expect(failed(report)).toEqual([
        'sensor.range/format/stream',
        'sensor.range/state/one-per-sensor',
      ]);
      expect(reasonOf(report, 'sensor.range/format/stream')).toContain('sensor');
    },
  );

  it(
    'fails the IMU checks when orientation_quaternion is missing, or not a unit quaternion',
    { timeout: 60_000 },
    async () => {
      const missing = await check({ imuWithoutQuaternion: true }, ['sensor.imu'], ALL_FEATURES);
      expect(failed(missing.report)).toEqual(expect.arrayContaining(['sensor.imu/format/stream']));
      expect(reasonOf(missing.report, 'sensor.imu/format/stream')).toContain(
        'orientation_quaternion',
      );
      const skewed = await check({ imuNotUnitQuaternion: true }, ['sensor.imu'], ALL_FEATURES);
      expect(failed(skewed.report)).toEqual(['sensor.imu/state/orientation']);
    },
  );

  it(
    'checks the mDNS announcement when asked: found with the queried caps, missing, or with other caps',
    { timeout: 60_000 },
    async () => {
      const run = async (announce: 'right' | 'none' | 'other caps') => {
        const deviceId = `fake-mdns-${(next += 1)}-${process.pid}`;
        const device = startFakeSpecDevice(nc, deviceId);
        const caps = announce === 'other caps' ? device.caps.slice(1) : device.caps;
        const announcer =
          announce === 'none' ? undefined : await announceTafyNode({ deviceId, caps, port: 4222 });
        await nc.flush();
        try {
          const report = await runCompliance({
            connection: nc,
            device: deviceId,
            capabilities: ['system'],
            samples: 3,
            announceTimeoutMs: 3000,
            mdns: true,
            mdnsTimeoutMs: 2500,
          });
          return report.checks.find((c) => c.id === 'system/capability/mdns-announcement');
        } finally {
          device.close();
          await announcer?.stop();
        }
      };
      expect(await run('right')).toMatchObject({ status: 'pass' });
      const missing = await run('none');
      expect(missing?.status).toBe('fail');
      expect(missing?.reason).toContain('no _tafynode._tcp node with device_id');
      const other = await run('other caps');
      expect(other?.status).toBe('fail');
      expect(other?.reason).toContain("the TXT record's caps are");
      // not asked for: not part of the run
      const { report } = await check({}, ['system']);
      expect(report.checks.map((c) => c.id)).not.toContain('system/capability/mdns-announcement');
    },
  );

  it(
    'stops after the running check when aborted, and reports the run as not complete',
    { timeout: 60_000 },
    async () => {
      const device = startFakeSpecDevice(nc, 'fake-aborted');
      await nc.flush();
      const abort = new AbortController();
      try {
        const report = await runCompliance({
          connection: nc,
          device: 'fake-aborted',
          samples: 3,
          signal: abort.signal,
          onProgress: (event) => {
            if (event.type === 'result') abort.abort();
          },
        });
        expect(report.checks.length).toBe(1);
        expect(report.aborted).toBe(true);
        expect(report.ok).toBe(false);
        expect(device.moving).toBe(false);
      } finally {
        device.close();
      }
    },
  );
});
