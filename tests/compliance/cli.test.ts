// `hal test hal ...` as a user runs it: the real bin as a child process against a gateway serving
// SimulationHAL on a real nats-server, and in-process (runHal) against a broken device.
import { runHal } from '@hal/cli';
import type { ComplianceReport } from '@hal/compliance';
import { serveHalOnNats } from '@hal/nats';
import type { HalGateway } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { connect } from '@nats-io/transport-node';
import type { NatsConnection } from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { runHalProcess } from '../helpers/hal-process.js';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';
import { startFakeSpecDevice } from './fake-spec-device.js';
import type { FakeSpecDevice } from './fake-spec-device.js';

let server: NatsServer;
let nc: NatsConnection;
let hal: SimulationHAL;
let gateway: HalGateway;
let broken: FakeSpecDevice;

beforeAll(async () => {
  server = await startNatsServer();
  nc = await connect({ servers: server.url });
  hal = new SimulationHAL({ clock: 'realtime' });
  await hal.initialize();
  gateway = await serveHalOnNats(hal, { servers: server.url, deviceId: 'sim-cli' });
  broken = startFakeSpecDevice(nc, 'fake-broken', { acceptsOutOfRange: true });
  await nc.flush();
}, 30_000);

// Every check group but timing, as `--group` options. What a latency or rate check measures here
// is this loaded machine as much as the device, so the runs whose exit code is asserted leave it
// out; the JSON run below runs it and holds the exit code to its verdict.
const NOT_TIMING = ['format', 'errors', 'capability', 'state'].flatMap((g) => ['--group', g]);

afterAll(async () => {
  broken?.close();
  await gateway?.close();
  await hal?.cleanup();
  await nc?.close();
  await stopAllNatsServers();
});

describe('hal test hal', () => {
  it(
    'checks motor.differential of a device as a process: progress on stderr, the table on stdout, exit 0',
    { timeout: 120_000 },
    async () => {
      const run = await runHalProcess(
        [
          'test',
          'hal',
          '--device',
          'sim-cli',
          '--capability',
          'motor.differential',
          ...NOT_TIMING,
          '--nats',
          server.url,
        ],
        90_000,
      );
      expect(run.code, run.stderr).toBe(0);
      expect(run.stderr).toContain('checking sim-cli');
      expect(run.stderr).toContain('PASS  motor.differential/state/drive-forward');
      expect(run.stdout).toMatch(/^RESULT +CAPABILITY +GROUP +CHECK +MEASURED +SPEC$/m);
      expect(run.stdout).toMatch(/PASS +motor\.differential +errors +a velocity beyond the robot/);
      expect(run.stdout).not.toMatch(/ timing /);
      expect(run.stdout).toMatch(
        /\d+ passed, 0 failed, 0 skipped in [\d.]+ s: COMPLIANT \(timing not checked\)/,
      );
      expect(run.stdout).not.toContain('system.health.req');
    },
  );

  it(
    'writes the report as JSON with --json, for the default device when --device is left out',
    { timeout: 120_000 },
    async () => {
      const run = await runHalProcess(
        ['--json', 'test', 'hal', '--capability', 'system', '--samples', '5', '--nats', server.url],
        90_000,
      );
      const report = JSON.parse(run.stdout) as ComplianceReport;
      expect(report.deviceId).toBe('sim-cli');
      expect(report.addressed).toBeUndefined();
      expect(report.groups).toEqual(['format', 'timing', 'errors', 'capability', 'state']);
      expect(report.checks.find((c) => c.id === 'system/timing/health')?.measured?.samples).toBe(5);
      // every group ran, timing too: the exit code and stderr follow the report's verdict
      const failedIds = report.checks.filter((c) => c.status === 'fail').map((c) => c.id);
      expect(failedIds.filter((id) => !id.includes('/timing/'))).toEqual([]);
      expect(report.ok).toBe(failedIds.length === 0);
      expect(run.code, run.stderr).toBe(report.ok ? 0 : 1);
      if (report.ok) expect(run.stderr).toBe('');
      else expect(JSON.parse(run.stderr)).toMatchObject({ error: { code: 'CHECK_FAILED' } });
    },
  );

  it(
    'exits 1 naming the failed check when a device accepts an out-of-range velocity',
    { timeout: 120_000 },
    async () => {
      const io = captureIO();
      const code = await runHal(
        [
          'test',
          'hal',
          '--device',
          'fake-broken',
          '--capability',
          'motor.differential',
          ...NOT_TIMING,
          '--samples',
          '5',
          '--nats',
          server.url,
        ],
        io,
      );
      expect(code).toBe(1);
      expect(io.stdout()).toMatch(/FAIL +motor\.differential +errors +a velocity beyond the robot/);
      expect(io.stdout()).toContain('NOT COMPLIANT');
      expect(io.stderr()).toMatch(
        /hal: CHECK_FAILED: 1 of \d+ checks failed: motor\.differential\/errors\/out-of-range\n$/,
      );
      expect(broken.moving).toBe(false);
    },
  );

  it(
    'tests every device seen on NATS with --all, and exits 1 naming the device that failed',
    { timeout: 180_000 },
    async () => {
      const io = captureIO();
      const code = await runHal(
        [
          '--json',
          'test',
          'hal',
          '--all',
          '--capability',
          'motor.differential',
          ...NOT_TIMING,
          '--samples',
          '5',
          '--nats',
          server.url,
        ],
        io,
      );
      expect(code).toBe(1);
      const reports = JSON.parse(io.stdout()) as ComplianceReport[];
      // the gateway is the default device too: seen on both subjects, tested once, by its id
      expect(reports.map((r) => [r.deviceId, r.addressed, r.ok])).toEqual([
        ['fake-broken', 'fake-broken', false],
        ['sim-cli', 'sim-cli', true],
      ]);
      const error = JSON.parse(io.stderr()) as { error: { code: string; message: string } };
      expect(error.error.code).toBe('CHECK_FAILED');
      expect(error.error.message).toMatch(
        /^1 of 2 devices failed: fake-broken \(1 of \d+ checks failed: motor\.differential\/errors\/out-of-range\)$/,
      );
    },
  );

  it('refuses an unknown --group as a usage error, sending nothing', async () => {
    const before = broken.requests;
    const io = captureIO();
    const code = await runHal(
      ['test', 'hal', '--device', 'fake-broken', '--group', 'speed', '--nats', server.url],
      io,
    );
    expect(code).toBe(2);
    expect(io.stderr()).toContain(
      'hal: USAGE: "--group" is one of format, timing, errors, capability, state, got "speed"',
    );
    expect(broken.requests).toBe(before);
  });

  it('refuses --all beside --device as a usage error, sending nothing', async () => {
    const io = captureIO();
    const code = await runHal(
      ['test', 'hal', '--all', '--device', 'sim-cli', '--nats', server.url],
      io,
    );
    expect(code).toBe(2);
    expect(io.stderr()).toContain('--all tests every device seen on NATS: leave out --device');
  });
});
