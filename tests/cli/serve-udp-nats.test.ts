// `hal serve --nats --udp` as a gateway process that owns the emulated robot (the firmware core
// run as cube-emulator) over UDP, with a real nats-server: `hal status --device` and
// `hal drive --device` reach the robot only through NATS, and what they do happens on the robot.
import { runHal } from '@hal/cli';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';
import { runHalProcess, startHalProcess } from '../helpers/hal-process.js';
import type { HalProcess } from '../helpers/hal-process.js';

interface ServeEvent {
  event: string;
  device?: string;
  mode?: string;
  nats?: { servers: string[]; subjects: string[] };
}

interface Status {
  device: { id: string; mode: string };
  safety: { emergencyStopped: boolean };
  health: { ready: boolean };
  pose: { position: { x: number } };
}

let nats: NatsServer;
let robot: Emulator;
let gateway: HalProcess<ServeEvent>;

const moves = () => robot.events.filter((e) => e.event === 'move_started').length;

async function status(): Promise<Status> {
  const run = await runHalProcess(
    ['--json', 'status', '--device', 'cube-gw', '--nats', nats.url],
    60_000,
  );
  expect(run.code, run.stderr).toBe(0);
  return JSON.parse(run.stdout) as Status;
}

async function drive(...argv: string[]) {
  const io = captureIO();
  const code = await runHal(
    ['--json', 'drive', ...argv, '--device', 'cube-gw', '--nats', nats.url],
    io,
  );
  return { code, io };
}

beforeAll(async () => {
  nats = await startNatsServer();
  robot = await startEmulator({ pty: false, deviceId: 'cube-emu' });
  gateway = startHalProcess<ServeEvent>([
    '--json',
    'serve',
    '--udp',
    `127.0.0.1:${robot.udpPort}`,
    '--nats',
    nats.url,
    '--device',
    'cube-gw',
  ]);
  await gateway.waitFor((e) => e.event === 'serving', 60_000);
}, 90_000);

afterAll(async () => {
  await gateway?.stop('SIGKILL');
  await stopAllEmulators();
  await stopAllNatsServers();
});

describe('hal serve --nats --udp, a gateway to the emulated robot', () => {
  it('serves the physical robot on its device subjects', () => {
    expect(gateway.events.find((e) => e.event === 'serving')).toEqual({
      event: 'serving',
      device: 'cube-gw',
      mode: 'physical',
      nats: {
        servers: [nats.url],
        subjects: ['hal.v1.dev.cube-gw.>', 'hal.v1.> (the default device)'],
      },
      mdns: { service: '_tafynode._tcp', name: 'cube-gw' },
    });
  });

  it('answers hal status --device from another process with the robot as it is', async () => {
    const seen = await status();
    expect(seen).toMatchObject({
      device: { id: 'cube-gw', mode: 'physical' },
      safety: { emergencyStopped: false },
      health: { ready: true },
    });
  }, 60_000);

  it('runs hal drive --device on the robot once, and the pose it reports is the robot one', async () => {
    const before = moves();
    const { code, io } = await drive('forward', '0.02');
    expect(code, io.stderr()).toBe(0);
    const moved = io.jsonLines()[0] as { pose: { position: { x: number } } };
    expect(moved.pose.position.x).toBeGreaterThan(0.015);
    expect(moves()).toBe(before + 1);
    expect((await status()).pose.position.x).toBeCloseTo(moved.pose.position.x, 3);
  }, 60_000);

  it("latches the robot's own e-stop through NATS, refuses motion until reset, then moves again", async () => {
    const stopped = await drive('estop', 'through the gateway');
    expect(stopped.code, stopped.io.stderr()).toBe(0);
    const trip = await robot.waitFor(
      (e) => e.event === 'trip' && e['reason'] === 'estop_command',
      10_000,
    );
    expect(trip['estop']).toBe(true);
    expect((await status()).safety.emergencyStopped).toBe(true);

    const before = moves();
    const refused = await drive('forward', '0.01');
    expect(refused.code).toBe(1);
    expect(JSON.parse(refused.io.stderr())).toMatchObject({
      error: { code: 'EMERGENCY_STOPPED' },
    });
    expect(moves()).toBe(before);

    expect((await drive('reset-estop')).code).toBe(0);
    const again = await drive('forward', '0.01');
    expect(again.code, again.io.stderr()).toBe(0);
    expect(moves()).toBe(before + 1);
  }, 90_000);

  it('refuses a second gateway for the same device before it opens the robot', async () => {
    const second = captureIO();
    const argv = ['--json', 'serve', '--udp', `127.0.0.1:${robot.udpPort}`, '--nats', nats.url];
    expect(await runHal([...argv, '--device', 'cube-gw'], second)).toBe(1);
    expect(JSON.parse(second.stderr())).toMatchObject({
      error: {
        code: 'INVALID_PARAMETER',
        message: expect.stringMatching(/^device "cube-gw" is already served/),
      },
    });
    // the serving gateway still owns the robot: its status is the robot's, ready
    expect((await status()).health.ready).toBe(true);
  });

  it('stops serving on Ctrl-C and lets the robot go', async () => {
    expect(await gateway.stop('SIGINT', 20_000)).toBe(0);
    expect(gateway.events.at(-1)).toEqual({ event: 'stopped' });
    const run = await runHalProcess(
      ['--json', 'status', '--device', 'cube-gw', '--nats', nats.url, '--connect-timeout', '2000'],
      60_000,
    );
    expect(run.code).toBe(1);
    expect(JSON.parse(run.stderr)).toMatchObject({ error: { code: 'NOT_CONNECTED' } });
    // the robot is free again: a program of its own takes it straight over UDP
    const direct = await runHalProcess(
      ['--json', 'status', '--udp', `127.0.0.1:${robot.udpPort}`],
      60_000,
    );
    expect(direct.code, direct.stderr).toBe(0);
    expect(JSON.parse(direct.stdout)).toMatchObject({ device: { mode: 'physical' } });
  }, 60_000);
});
