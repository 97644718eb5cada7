// `hal emulate` in-process: the real cube-emulator, announced with real mDNS on this machine.
import { randomBytes } from 'node:crypto';
import { afterEach, describe, expect, it } from 'vitest';
import { discoverRobots, findRobot } from '@hal/discovery';
import { captureIO } from '../testing/capture-io.js';
import type { CapturedIO } from '../testing/capture-io.js';
import { builtEmulatorPath } from '../emulate/emulator-path.fixture.js';
import { runHal } from '../program.js';

const uniqueId = () => `cube-emu-${randomBytes(4).toString('hex')}`;

/** Waits (bounded) until the captured output has a JSON line that matches. */
async function waitForLine(io: CapturedIO, match: (line: Record<string, unknown>) => boolean) {
  const deadline = Date.now() + 15_000;
  while (Date.now() < deadline) {
    const found = (io.jsonLines() as Record<string, unknown>[]).find(match);
    if (found) return found;
    await new Promise((resolve) => setTimeout(resolve, 25));
  }
  throw new Error(`no matching line; stdout: ${io.stdout()} stderr: ${io.stderr()}`);
}

const running: { io: CapturedIO; done: Promise<number> }[] = [];
afterEach(async () => {
  for (const run of running.splice(0)) {
    run.io.abort();
    await run.done;
  }
});

function emulate(args: string[]) {
  const io = captureIO();
  const done = runHal(['--json', 'emulate', '--emulator', builtEmulatorPath(), ...args], io);
  const run = { io, done };
  running.push(run);
  return run;
}

/** Runs `hal emulate` (human output) until it ends by itself: for the runs it refuses. */
async function emulateToEnd(args: string[]) {
  const io = captureIO();
  const code = await runHal(['emulate', '--emulator', builtEmulatorPath(), ...args], io);
  return { code, io };
}

describe('hal emulate', { timeout: 30_000 }, () => {
  it('prints where the robot listens, announces it, and stops cleanly when aborted', async () => {
    const id = uniqueId();
    const { io, done } = emulate(['--udp-port', '0', '--no-pty', '--device-id', id]);
    const ready = await waitForLine(io, (l) => l['event'] === 'ready');
    expect(ready).toMatchObject({
      deviceId: id,
      address: '127.0.0.1',
      auth: 'none',
      announced: true,
      service: '_hal-cube._udp',
    });
    const robot = await findRobot(id, { timeoutMs: 10_000 });
    expect(robot.port).toBe(ready['udpPort']);
    expect(robot.capabilities).toContain('locomotion.differential:v1.0');

    io.abort();
    expect(await done).toBe(0);
    expect(io.jsonLines()).toContainEqual({ event: 'stopped', deviceId: id });
    // the emulator's own last word came through too
    expect(io.jsonLines()).toContainEqual({ event: 'exit', reason: 'signal' });
    const after = await discoverRobots({ timeoutMs: 1500 });
    expect(after.map((r) => r.deviceId)).not.toContain(id);
  });

  it('does not announce with --no-announce', async () => {
    const id = uniqueId();
    const { io } = emulate(['--udp-port', '0', '--no-pty', '--no-announce', '--device-id', id]);
    const ready = await waitForLine(io, (l) => l['event'] === 'ready');
    expect(ready['announced']).toBe(false);
    const robots = await discoverRobots({ timeoutMs: 1500 });
    expect(robots.map((r) => r.deviceId)).not.toContain(id);
  });

  it('refuses a device id another robot already announces', async () => {
    const id = uniqueId();
    const first = emulate(['--udp-port', '0', '--no-pty', '--device-id', id]);
    await waitForLine(first.io, (l) => l['event'] === 'ready');
    const second = await emulateToEnd(['--udp-port', '0', '--no-pty', '--device-id', id]);
    expect(second.code).toBe(1);
    expect(second.io.stderr()).toMatch(/already announced.*choose another --device-id/);
  });

  it('fails with NOT_FOUND for an --emulator that is not a program', async () => {
    const io = captureIO();
    const code = await runHal(
      ['--json', 'emulate', '--emulator', '/nonexistent/cube-emulator'],
      io,
    );
    expect(code).toBe(1);
    expect(JSON.parse(io.stderr())).toMatchObject({ error: { code: 'NOT_FOUND' } });
  });

  it.each([
    [['--key', 'abc'], '"--key" must be'],
    [['--udp-port', '70000'], '"--udp-port" must be an integer in 0..65535'],
    [['--time-scale', '0'], '"--time-scale" must be'],
    [['--bind', 'localhost'], '"--bind" must be an IPv4 address'],
    [['--device-id', 'a.b'], 'a device id is'],
  ])('refuses bad options %j with a usage error', async (args, why) => {
    const io = captureIO();
    expect(await runHal(['emulate', ...args], io)).toBe(2);
    expect(io.stderr()).toContain(why);
  });

  it('passes the emulator refusal of a non-loopback bind without a key on', async () => {
    const { code, io } = await emulateToEnd(['--udp-port', '0', '--no-pty', '--bind', '0.0.0.0']);
    expect(code).toBe(1);
    expect(io.stderr()).toMatch(/refusing to listen on 0\.0\.0\.0 without a key/);
  });
});
