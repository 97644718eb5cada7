// The compliance runner against a gateway serving SimulationHAL on a real nats-server: a
// compliant device passes every check, addressed as the default device and as one of a fleet.
import { formatReport, runCompliance } from '@hal/compliance';
import type { ComplianceReport } from '@hal/compliance';
import { serveHalOnNats } from '@hal/nats';
import type { HalGateway } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { connect } from '@nats-io/transport-node';
import type { NatsConnection } from '@nats-io/transport-node';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';

let server: NatsServer;
let nc: NatsConnection;
let hal: SimulationHAL;
let gateway: HalGateway;

beforeAll(async () => {
  server = await startNatsServer();
  nc = await connect({ servers: server.url });
  // The real-time clock: a move takes as long as on the robot, so the state stream can show it.
  hal = new SimulationHAL({ clock: 'realtime', deviceId: 'sim-cube' });
  await hal.initialize();
  gateway = await serveHalOnNats(hal, {
    servers: server.url,
    deviceId: 'sim-cube',
    stateRateHz: 20,
  });
}, 30_000);

afterAll(async () => {
  await gateway?.close();
  await hal?.cleanup();
  await nc?.close();
  await stopAllNatsServers();
});

// Failures outside the timing group. A timing verdict holds a latency measured on this machine,
// with other test files on its cores, to the spec's limits: the timing checks here must measure,
// and bench/nats-spec.bench.ts holds the gateway to the spec's figures.
const failures = (report: ComplianceReport) =>
  report.checks
    .filter((c) => c.status === 'fail' && c.group !== 'timing')
    .map((c) => `${c.id}: ${c.reason}`);

describe('runCompliance against a gateway serving SimulationHAL', () => {
  it(
    'passes every check of every capability the simulated robot announces, and measures its timing',
    { timeout: 120_000 },
    async () => {
      const report = await runCompliance({ connection: nc, device: 'sim-cube' });
      expect(failures(report), formatReport(report)).toEqual([]);
      expect(report.deviceId).toBe('sim-cube');
      // the simulated robot has all of them: nothing skipped
      expect(report.capabilities).toEqual([
        'system',
        'motor.differential',
        'safety',
        'camera',
        'sensor.imu',
        'sensor.range',
      ]);
      expect(report.summary.skipped).toBe(0);
      expect(report.checks.some((c) => c.id.endsWith('not-implemented'))).toBe(false);
      const groups = new Set(report.checks.filter((c) => c.status === 'pass').map((c) => c.group));
      groups.delete('timing');
      expect([...groups].sort()).toEqual(['capability', 'errors', 'format', 'state']);
      for (const timing of report.checks.filter((c) => c.group === 'timing')) {
        expect(timing.status, timing.id).not.toBe('skip');
        expect(timing.measured?.samples ?? timing.rateHz, timing.id).toBeGreaterThan(0);
      }
      const stop = report.checks.find((c) => c.id === 'motor.differential/timing/stop-command');
      expect(stop?.measured?.samples).toBe(20);
      expect(stop?.latencyClass?.limitMs).toBe(10);
      // it leaves the robot as it found it: stopped, not e-stopped
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      expect((await hal.locomotion.getPose()).velocity.linear).toBe(0);
    },
  );
});
