// `hal fleet --config <file>`: a simulated robot and the emulated robot (cube-emulator over UDP)
// as one fleet, with no NATS anywhere: health, a synchronized run and the fleet e-stop, in-process
// and once as the real program; a bad config file is refused with its problems by path.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { runHalProcess } from '../helpers/hal-process.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';

interface Health {
  device: string;
  type: string;
  online: boolean;
  emergencyStopped: boolean;
}

let dir: string;
let robot: Emulator;
let config: string;

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-fleet-config-'));
  robot = await startEmulator({ pty: false, deviceId: 'cube-1' });
  config = join(dir, 'fleet.json');
  await writeFile(
    config,
    JSON.stringify({
      mode: 'synchronized',
      devices: [
        { type: 'simulated', id: 'sim-1', clock: 'fast' },
        {
          type: 'physical',
          id: 'cube-1',
          connection: { type: 'wifi', host: '127.0.0.1', udpPort: robot.udpPort },
        },
      ],
    }),
  );
}, 30_000);

afterAll(async () => {
  await stopAllEmulators();
  await rm(dir, { recursive: true, force: true });
});

async function hal(...argv: string[]) {
  const io = captureIO();
  const code = await runHal(argv, io);
  return { code, io };
}

describe('hal fleet --config', () => {
  it('reads the health of a simulated and a physical device without NATS', async () => {
    const { code, io } = await hal('--json', 'fleet', 'health', '--config', config);
    expect(io.stderr()).not.toContain('error');
    expect(code).toBe(0);
    const [doc] = io.jsonLines() as [{ health: Health[] }];
    expect(doc.health.map((h) => [h.device, h.type, h.online, h.emergencyStopped])).toEqual([
      ['sim-1', 'simulated', true, false],
      ['cube-1', 'physical', true, false],
    ]);
  }, 30_000);

  it('runs a synchronized move on both, the emulated robot running it once', async () => {
    const before = robot.events.filter((e) => e.event === 'move_started').length;
    const { code, io } = await hal(
      'fleet',
      'run',
      '--config',
      config,
      '--mode',
      'synchronized',
      '--command',
      'forward:1cm',
    );
    expect(io.stderr()).not.toContain('hal:');
    expect(code).toBe(0);
    expect(io.stdout()).toMatch(/^sim-1 +ok/m);
    expect(io.stdout()).toMatch(/^cube-1 +ok/m);
    expect(io.stdout()).toContain('synchronized moveForward: 2 ok, 0 failed');
    expect(robot.events.filter((e) => e.event === 'move_started')).toHaveLength(before + 1);
  }, 60_000);

  it("runs the config file's mode when --mode is not given, and refuses a file whose mode runs nothing", async () => {
    const before = robot.events.filter((e) => e.event === 'move_started').length;
    const { code, io } = await hal('fleet', 'run', '--config', config, '--command', 'forward:1cm');
    expect(io.stderr()).not.toContain('hal:');
    expect(code).toBe(0);
    expect(io.stdout()).toContain('synchronized moveForward: 2 ok, 0 failed');
    expect(robot.events.filter((e) => e.event === 'move_started')).toHaveLength(before + 1);

    const independent = join(dir, 'independent.json');
    await writeFile(independent, JSON.stringify({ devices: [{ type: 'simulated', id: 'sim-1' }] }));
    const bad = await hal('fleet', 'run', '--config', independent, '--command', 'forward:1cm');
    expect(bad.code).toBe(2);
    expect(bad.io.stderr()).toContain('its mode is "independent"');
  }, 60_000);

  it('narrows the fleet with --device and refuses a device the file lacks', async () => {
    const one = await hal('--json', 'fleet', 'health', '--config', config, '--device', 'sim-1');
    expect(one.code).toBe(0);
    const [doc] = one.io.jsonLines() as [{ health: Health[] }];
    expect(doc.health.map((h) => h.device)).toEqual(['sim-1']);
    const bad = await hal('fleet', 'health', '--config', config, '--device', 'cube-9');
    expect(bad.code).toBe(2);
    expect(bad.io.stderr()).toContain('hal: USAGE: --device cube-9: not in the config file');
  }, 30_000);

  it('ends a leader-follower run of fast-clock simulated robots once the follower settles', async () => {
    const fast = join(dir, 'fast-fleet.json');
    await writeFile(
      fast,
      JSON.stringify({
        devices: [
          { type: 'simulated', id: 'sim-a', clock: 'fast' },
          { type: 'simulated', id: 'sim-b', clock: 'fast', start: { x: -0.3, y: 0, yaw: 0 } },
        ],
      }),
    );
    const io = captureIO();
    const run = runHal(
      [
        '--json',
        'fleet',
        'run',
        '--config',
        fast,
        '--mode',
        'leader-follower',
        '--leader',
        'sim-a',
        '--command',
        'forward:10cm',
        '--settle-timeout-ms',
        '5000',
      ],
      io,
    );
    // it used to stay at "followers settling..." for ever: give up (and stop it) after 15 s
    let timer: NodeJS.Timeout | undefined;
    const late = new Promise<'late'>(
      (resolve) => (timer = setTimeout(() => resolve('late'), 15_000)),
    );
    const code = await Promise.race([run, late]);
    clearTimeout(timer);
    if (code === 'late') {
      io.abort();
      await run;
    }
    expect(code, io.stderr()).toBe(0);
    const [doc] = io.jsonLines() as [
      { formation: { reason: string; followers: { errorM: number }[] } },
    ];
    expect(doc.formation.reason).toBe('leader-stopped');
    expect(doc.formation.followers[0]?.errorM).toBeLessThan(0.03);
  }, 30_000);

  it('refuses a config file with its problems by path, and a missing one as NOT_FOUND', async () => {
    const invalid = join(dir, 'invalid.json');
    await writeFile(
      invalid,
      JSON.stringify({ devices: [{ type: 'physical', id: 'x', connection: { type: 'usb' } }] }),
    );
    const bad = await hal('--json', 'fleet', 'health', '--config', invalid);
    expect(bad.code).toBe(1);
    const error = JSON.parse(bad.io.stderr()) as {
      error: { code: string; message: string; details: { issues: { path: unknown[] }[] } };
    };
    expect(error.error.code).toBe('INVALID_PARAMETER');
    expect(error.error.message).toContain('devices.0.connection.type');
    expect(error.error.details.issues[0]?.path).toEqual(['devices', 0, 'connection', 'type']);
    const missing = await hal('fleet', 'health', '--config', join(dir, 'absent.json'));
    expect(missing.code).toBe(1);
    expect(missing.io.stderr()).toContain('hal: NOT_FOUND: --config');
  });

  it('e-stops the fleet through the real program, and the robot keeps the latch for the next session', async () => {
    const run = await runHalProcess(
      ['--json', 'fleet', 'estop', 'end of shift', '--config', config],
      60_000,
    );
    expect(run.stderr).not.toContain('"error"');
    expect(run.code).toBe(0);
    const report = JSON.parse(run.stdout) as { succeeded: string[]; failed: string[] };
    expect(report.succeeded).toEqual(['sim-1', 'cube-1']);
    const trip = await robot.waitFor(
      (e) => e.event === 'trip' && e['reason'] === 'estop_command',
      10_000,
    );
    expect(trip['estop']).toBe(true);

    const after = await hal('--json', 'fleet', 'health', '--config', config, '--device', 'cube-1');
    expect(after.code).toBe(0);
    const [doc] = after.io.jsonLines() as [{ health: Health[] }];
    expect(doc.health[0]).toMatchObject({ device: 'cube-1', online: true, emergencyStopped: true });
  }, 90_000);
});
