// `hal fleet` against a real nats-server and a robot host serving three simulated robots: run
// in-process (as `hal` parses its argv) and once as the real program in its own process.
import { runHal } from '@hal/cli';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { runHalProcess } from '../helpers/hal-process.js';
import { startHostProcess, stopAllHostProcesses } from '../physical/host-process.js';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';

const DEVICES = ['--device', 'c00', '--device', 'c01', '--device', 'c02'];
let server: NatsServer;

async function hal(...argv: string[]) {
  const io = captureIO();
  const code = await runHal([...argv, '--nats', server.url], io);
  return { code, io };
}

beforeAll(async () => {
  server = await startNatsServer();
  const host = startHostProcess('../../fleet/processes/fleet-gateways.ts', [
    server.url,
    'c',
    '3',
    '8',
    '10',
    'column',
  ]);
  await host.waitFor((e) => e.event === 'serving', 30_000);
}, 60_000);

afterAll(async () => {
  await stopAllHostProcesses();
  await stopAllNatsServers();
});

describe('hal fleet', () => {
  it('finds the devices from their announcements and lists them', async () => {
    const { code, io } = await hal('--json', 'fleet', 'devices', '--discover-ms', '5500');
    expect(code).toBe(0);
    const [doc] = io.jsonLines() as Array<{ devices: Array<Record<string, unknown>> }>;
    expect(doc?.devices.map((d) => d['device'])).toEqual(['c00', 'c01', 'c02']);
    expect(doc?.devices[0]).toMatchObject({ online: true, mode: 'simulation' });
    expect(doc?.devices[0]).toMatchObject({ type: 'v1-stepper-cube' });
    expect(doc?.devices[0]?.['capabilities']).toEqual(
      expect.arrayContaining(['locomotion.differential:v1.0', 'safety.estop:v1.0']),
    );
  }, 30_000);

  it('runs a synchronized move and prints every device its own line', async () => {
    const { code, io } = await hal(
      'fleet',
      'run',
      '--mode',
      'synchronized',
      '--command',
      'forward:1cm',
      ...DEVICES,
    );
    expect(io.stderr()).toContain('synchronized moveForward on 3 device(s)');
    expect(code).toBe(0);
    expect(io.stdout()).toMatch(/c00\s+ok/);
    expect(io.stdout()).toMatch(/c02\s+ok/);
    expect(io.stdout()).toContain('synchronized moveForward: 3 ok, 0 failed');
  }, 30_000);

  it('runs leader-follower: the followers keep their column behind the leader', async () => {
    const { code, io } = await hal(
      '--json',
      'fleet',
      'run',
      '--mode',
      'leader-follower',
      '--leader',
      'c00',
      '--formation',
      'column',
      '--spacing',
      '0.25',
      '--command',
      'forward:10cm',
      ...DEVICES,
    );
    expect(io.stderr()).toBe('');
    expect(code).toBe(0);
    const [doc] = io.jsonLines() as Array<{
      leader: { result: { success: boolean } };
      formation: { reason: string; followers: Array<{ device: string; errorM: number }> };
    }>;
    expect(doc?.leader.result.success).toBe(true);
    expect(doc?.formation.reason).toBe('leader-stopped');
    expect(doc?.formation.followers.map((f) => f.device)).toEqual(['c01', 'c02']);
    for (const f of doc?.formation.followers ?? []) expect(f.errorM).toBeLessThan(0.03);
  }, 90_000);

  it('e-stops every device, refuses motion until reset, then moves again', async () => {
    const stop = await hal('fleet', 'estop', 'drill', ...DEVICES);
    expect(stop.code).toBe(0);
    expect(stop.io.stdout()).toContain('e-stop: 3 ok, 0 failed');
    const refused = await hal(
      '--json',
      'fleet',
      'run',
      '--mode',
      'synchronized',
      '--command',
      'forward:1cm',
      ...DEVICES,
    );
    expect(refused.code).toBe(1);
    const [report] = refused.io.jsonLines() as Array<{
      results: Array<{ result: { code?: string } }>;
    }>;
    expect(report?.results.map((r) => r.result.code)).toEqual([
      'EMERGENCY_STOPPED',
      'EMERGENCY_STOPPED',
      'EMERGENCY_STOPPED',
    ]);
    expect(JSON.parse(refused.io.stderr().trim())).toMatchObject({ error: { code: 'FAILED' } });
    expect((await hal('fleet', 'reset', ...DEVICES)).code).toBe(0);
    const again = await hal(
      'fleet',
      'run',
      '--mode',
      'synchronized',
      '--command',
      'forward:1cm',
      ...DEVICES,
    );
    expect(again.code).toBe(0);
  }, 60_000);

  it('refuses a bad command, a missing leader and a bad device id as usage errors', async () => {
    const bad = await hal(
      'fleet',
      'run',
      '--mode',
      'synchronized',
      '--command',
      'fly:3',
      ...DEVICES,
    );
    expect(bad.code).toBe(2);
    expect(bad.io.stderr()).toContain('hal: USAGE: --command "fly:3"');
    const noLeader = await hal(
      'fleet',
      'run',
      '--mode',
      'leader-follower',
      '--command',
      'forward:1cm',
      ...DEVICES,
    );
    expect(noLeader.code).toBe(2);
    expect(noLeader.io.stderr()).toContain('needs --leader');
    const badId = await hal('fleet', 'health', '--device', 'a.b');
    expect(badId.code).toBe(2);
    expect(badId.io.stderr()).toContain('a device id is 1-64 letters');
  });

  it('reports a device that does not answer as offline, and exits through the real program', async () => {
    const run = await runHalProcess(
      [
        '--json',
        'fleet',
        'health',
        '--device',
        'c01',
        '--device',
        'nobody',
        '--offline-after-ms',
        '1000',
        '--nats',
        server.url,
      ],
      50_000,
    );
    expect(run.code, run.stderr).toBe(0);
    const doc = JSON.parse(run.stdout.trim()) as {
      health: Array<{ device: string; online: boolean }>;
    };
    expect(doc.health.map((h) => [h.device, h.online])).toEqual([
      ['c01', true],
      ['nobody', false],
    ]);
  }, 60_000);
});
