// `hal status` and `hal drive` against the emulated robot (the firmware core as a process) over
// UDP and over its pseudo-terminal: each run is a new host session, as for a user at a shell.
import { runHal } from '@hal/cli';
import { RemoteHAL } from '@hal/remote';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';
import type { CapturedIO } from './capture-io.js';

interface StatusDoc {
  device: { id: string; mode: string; type: string };
  capabilities: string[];
  pose: { position: { x: number }; rotation: { yaw: number }; velocity: { linear: number } };
  safety: { emergencyStopped: boolean; reason?: string };
}

let emulator: Emulator;
let udp: string[];

beforeAll(async () => {
  emulator = await startEmulator({ timeScale: 4, deviceId: 'cube-cli', hostTimeoutMs: 5000 });
  udp = ['--udp', `127.0.0.1:${emulator.udpPort}`, '--time-scale', '4'];
});
afterAll(stopAllEmulators);

async function hal(
  argv: string[],
  io: CapturedIO = captureIO(),
): Promise<{ code: number; io: CapturedIO }> {
  return { code: await runHal(argv, io), io };
}

async function status(target = udp): Promise<StatusDoc> {
  const { code, io } = await hal(['--json', 'status', ...target]);
  expect(code, io.stderr()).toBe(0);
  return io.jsonLines()[0] as StatusDoc;
}

describe('hal on the emulated robot', () => {
  it("reports the robot's own id, its capabilities and its safety state", async () => {
    const doc = await status();
    expect(doc.device).toEqual({ id: 'cube-cli', mode: 'physical', type: 'v1-stepper-cube' });
    expect(doc.capabilities).toEqual(expect.arrayContaining(['safety.estop:v1.0']));
    expect(doc.safety.emergencyStopped).toBe(false);
  });

  it('drives forward and turns, and reports the pose after each motion', async () => {
    const forward = await hal(['--json', 'drive', 'forward', '0.05', ...udp]);
    expect(forward.code, forward.io.stderr()).toBe(0);
    const moved = forward.io.jsonLines()[0] as {
      pose: StatusDoc['pose'];
      result: { mode: string };
    };
    expect(moved.result.mode).toBe('physical');
    expect(moved.pose.position.x).toBeCloseTo(0.05, 2);
    const turn = await hal(['--json', 'drive', 'turn', '-45', ...udp]);
    expect(turn.code, turn.io.stderr()).toBe(0);
    const turned = turn.io.jsonLines()[0] as { pose: StatusDoc['pose'] };
    expect(turned.pose.rotation.yaw).toBeCloseTo(-Math.PI / 4, 1);
  });

  it('reads the same robot over its serial link', async () => {
    const doc = await status(['--serial', emulator.pty, '--time-scale', '4']);
    expect(doc.device.id).toBe('cube-cli');
  });

  it('keeps the e-stop latched between runs until reset-estop', async () => {
    expect((await hal(['drive', 'estop', 'cli test', ...udp])).code).toBe(0);
    const latched = await status();
    expect(latched.safety.emergencyStopped).toBe(true);
    const refused = await hal(['--json', 'drive', 'forward', '0.02', ...udp]);
    expect(refused.code).toBe(1);
    // the error document is the last line (warnings before it are JSON lines too)
    const lines = refused.io
      .stderr()
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l) as unknown);
    expect(lines.at(-1)).toMatchObject({ error: { code: 'EMERGENCY_STOPPED' } });
    // the hint is the command to type, with this robot's options, not the library's method
    const { message } = (lines.at(-1) as { error: { message: string } }).error;
    expect(message).toBe(
      `forward 0.02 m: the emergency stop is latched; reset it with: hal drive reset-estop ${udp.join(' ')}`,
    );
    expect((await hal(['drive', 'reset-estop', ...udp])).code).toBe(0);
    expect((await status()).safety.emergencyStopped).toBe(false);
  });

  it('stops the robot when interrupted mid-motion', async () => {
    const io = captureIO();
    const before = emulator.events.length;
    const run = runHal(['--json', 'drive', 'forward', '0.18', ...udp], io);
    const started = await emulator.waitFor(
      (e) => e.event === 'move_started' && emulator.events.indexOf(e) >= before,
      20_000,
    );
    await new Promise((resolve) => setTimeout(resolve, 300));
    io.abort();
    expect(await run).toBe(130);
    // the robot itself says the move was stopped short, not finished
    const finished = await emulator.waitFor(
      (e) => e.event === 'move_finished' && e['move_id'] === started['move_id'],
      5000,
    );
    expect(finished['outcome']).toBe('stopped');
    expect(Number(finished['left_steps'])).toBeLessThan(Number(started['left_steps']));
  });

  it('serves the robot with hal serve, and stops it when serving ends on Ctrl-C', async () => {
    const io = captureIO();
    const serving = runHal(
      ['--json', 'serve', ...udp, '--device', 'cube-served', '--ws-port', '0'],
      io,
    );
    const deadline = Date.now() + 20_000;
    while (io.jsonLines().length === 0 && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    const { ws } = io.jsonLines()[0] as { ws: { url: string } };
    const remote = new RemoteHAL({ url: ws.url, reconnect: false });
    await remote.initialize();
    expect(remote.getDeviceInfo().id).toBe('cube-served');
    const before = emulator.events.length;
    expect((await remote.locomotion.drive(200, 200)).success).toBe(true); // until stopped
    const started = await emulator.waitFor(
      (e) => e.event === 'move_started' && emulator.events.indexOf(e) >= before,
    );
    io.abort();
    expect(await serving).toBe(0);
    const finished = await emulator.waitFor(
      (e) => e.event === 'move_finished' && e['move_id'] === started['move_id'],
      5000,
    );
    expect(finished['outcome']).toBe('stopped');
    expect(io.jsonLines().at(-1)).toEqual({ event: 'stopped' });
    await remote.cleanup();
  });
});
