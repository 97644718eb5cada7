// `hal serve --nats` and `hal status` as two processes, as users run them, through a real
// nats-server: the gateway owns the simulator; every other program reaches it through NATS.
import { runHal } from '@hal/cli';
import { discoverTafyNodes } from '@hal/discovery';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';
import { captureIO } from './capture-io.js';
import { runHalProcess, startHalProcess } from '../helpers/hal-process.js';
import type { HalProcess } from '../helpers/hal-process.js';

interface ServeEvent {
  event: string;
  device?: string;
  nats?: { servers: string[]; subjects: string[] };
  mdns?: { service: string; name: string } | { error: string };
}

let nats: NatsServer;
let serve: HalProcess<ServeEvent>;

beforeAll(async () => {
  nats = await startNatsServer();
  serve = startHalProcess<ServeEvent>([
    '--json',
    'serve',
    '--sim',
    '--time-scale',
    '10',
    '--nats',
    nats.url,
    '--device',
    'desk-sim',
  ]);
  await serve.waitFor((e) => e.event === 'serving');
});
afterAll(async () => {
  await serve?.stop('SIGKILL');
  await stopAllNatsServers();
});

describe('hal serve --nats', () => {
  it('says where it serves: the device subjects and the default device', () => {
    const serving = serve.events.find((e) => e.event === 'serving');
    expect(serving).toEqual({
      event: 'serving',
      device: 'desk-sim',
      mode: 'simulation',
      nats: {
        servers: [nats.url],
        subjects: ['hal.v1.dev.desk-sim.>', 'hal.v1.> (the default device)'],
      },
      mdns: { service: '_tafynode._tcp', name: 'desk-sim' },
    });
  });

  it("is announced by mDNS as the spec's _tafynode._tcp, with its device id and capabilities", async () => {
    const nodes = await discoverTafyNodes({ timeoutMs: 2500 });
    const node = nodes.find((n) => n.deviceId === 'desk-sim');
    expect(node).toBeDefined();
    expect(node?.port).toBe(Number(new URL(nats.url).port));
    expect(node?.servers).toEqual([nats.url]);
    const status = await runHalProcess([
      '--json',
      'status',
      '--device',
      'desk-sim',
      '--nats',
      nats.url,
    ]);
    const announced = (JSON.parse(status.stdout) as { capabilities: string[] }).capabilities;
    expect([...(node?.caps ?? [])].sort()).toEqual([...announced].sort());
  });

  it("passes the compliance runner's mDNS check, asked for with hal test hal --mdns", async () => {
    const run = await runHalProcess(
      [
        '--json',
        'test',
        'hal',
        '--device',
        'desk-sim',
        '--capability',
        'system',
        '--samples',
        '3',
        '--mdns',
        '--nats',
        nats.url,
      ],
      60_000,
    );
    expect(run.code, run.stderr).toBe(0);
    const report = JSON.parse(run.stdout) as {
      checks: { id: string; status: string; reason: string }[];
    };
    expect(report.checks.find((c) => c.id === 'system/capability/mdns-announcement')).toMatchObject(
      {
        status: 'pass',
      },
    );
  }, 90_000);

  it('answers hal status --device from another process', async () => {
    const run = await runHalProcess([
      '--json',
      'status',
      '--device',
      'desk-sim',
      '--nats',
      nats.url,
    ]);
    expect(run.code, run.stderr).toBe(0);
    const status = JSON.parse(run.stdout) as Record<string, unknown>;
    expect(status).toMatchObject({
      device: { id: 'desk-sim', mode: 'simulation' },
      safety: { emergencyStopped: false },
      health: { ready: true },
    });
    expect(status['capabilities']).toEqual(
      expect.arrayContaining(['locomotion.differential:v1.0']),
    );
  });

  it('is the default device for a client that names none, and drives through NATS', async () => {
    const io = captureIO();
    expect(await runHal(['--json', 'drive', 'forward', '0.05', '--nats', nats.url], io)).toBe(0);
    const moved = io.jsonLines()[0] as { pose: { position: { x: number } } };
    expect(moved.pose.position.x).toBeGreaterThan(0.03);
    const status = await runHalProcess([
      '--json',
      'status',
      '--device',
      'desk-sim',
      '--nats',
      nats.url,
    ]);
    const pose = (JSON.parse(status.stdout) as { pose: { position: { x: number } } }).pose;
    expect(pose.position.x).toBeCloseTo(moved.pose.position.x, 3);
    // without --device, the default device is named by the id it is served as
    const bare = captureIO();
    expect(await runHal(['--json', 'status', '--nats', nats.url], bare)).toBe(0);
    expect((bare.jsonLines()[0] as { device: { id: string } }).device.id).toBe('desk-sim');
  });

  it('shows the e-stop and its reason in hal status over NATS, until it is reset', async () => {
    const target = ['--device', 'desk-sim', '--nats', nats.url];
    expect(await runHal(['drive', 'estop', 'bumper hit', ...target], captureIO())).toBe(0);
    const json = captureIO();
    expect(await runHal(['--json', 'status', ...target], json)).toBe(0);
    expect((json.jsonLines()[0] as { safety: unknown }).safety).toEqual({
      emergencyStopped: true,
      reason: 'bumper hit',
    });
    const human = captureIO();
    expect(await runHal(['status', ...target], human)).toBe(0);
    expect(human.stdout()).toMatch(/^safety {8}EMERGENCY STOP \(bumper hit\)$/m);
    expect(await runHal(['drive', 'reset-estop', ...target], captureIO())).toBe(0);
    const after = captureIO();
    expect(await runHal(['--json', 'status', ...target], after)).toBe(0);
    expect((after.jsonLines()[0] as { safety: unknown }).safety).toEqual({
      emergencyStopped: false,
    });
  });

  it('refuses to serve a device id that is already served, and a second default device', async () => {
    const same = captureIO();
    const args = ['--json', 'serve', '--sim', '--nats', nats.url];
    expect(await runHal([...args, '--device', 'desk-sim'], same)).toBe(1);
    expect(JSON.parse(same.stderr())).toEqual({
      error: {
        code: 'INVALID_PARAMETER',
        message: expect.stringMatching(
          /^device "desk-sim" is already served on this NATS \(a gateway answers hal\.v1\.dev\.desk-sim\.system\.health\.req\)/,
        ),
        details: expect.objectContaining({ deviceId: 'desk-sim' }) as unknown,
      },
    });
    const secondDefault = captureIO();
    expect(await runHal([...args, '--device', 'desk-sim-2'], secondDefault)).toBe(1);
    expect(JSON.parse(secondDefault.stderr())).toMatchObject({
      error: {
        code: 'INVALID_PARAMETER',
        message: expect.stringContaining('--no-default-device'),
      },
    });
    // under its own id and not as the default device, it is served
    const own = captureIO();
    const serving = runHal([...args, '--device', 'desk-sim-2', '--no-default-device'], own);
    const deadline = Date.now() + 20_000;
    while (own.jsonLines().length === 0 && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    expect(own.jsonLines()[0]).toMatchObject({ event: 'serving', device: 'desk-sim-2' });
    own.abort();
    expect(await serving).toBe(0);
  });

  it('says NOT_CONNECTED for a device nobody serves, within the connect timeout', async () => {
    const started = Date.now();
    const run = await runHalProcess([
      '--json',
      'status',
      '--device',
      'nobody',
      '--nats',
      nats.url,
      '--connect-timeout',
      '2000',
    ]);
    expect(run.code).toBe(1);
    expect(JSON.parse(run.stderr)).toMatchObject({ error: { code: 'NOT_CONNECTED' } });
    expect(Date.now() - started).toBeLessThan(20_000); // bounded, process start-up included
  });

  it('stops serving cleanly on Ctrl-C', async () => {
    const second = startHalProcess<ServeEvent>([
      '--json',
      'serve',
      '--sim',
      '--nats',
      nats.url,
      '--device',
      'second',
      '--no-default-device',
    ]);
    await second.waitFor((e) => e.event === 'serving');
    expect(await second.stop('SIGINT')).toBe(0);
    expect(second.events.at(-1)).toEqual({ event: 'stopped' });
    const gone = await runHalProcess([
      'status',
      '--device',
      'second',
      '--nats',
      nats.url,
      '--connect-timeout',
      '2000',
    ]);
    expect(gone.code).toBe(1);
    expect(gone.stderr).toContain('hal: NOT_CONNECTED');
  });
});
