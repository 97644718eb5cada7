import { serveHal } from '@hal/remote/server';
import type { HalServer } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';
import { fakeTty } from '../testing/fake-tty.js';
import type { FakeTty } from '../testing/fake-tty.js';

/** Polls `check` until it is true, at most `timeoutMs`. */
async function until(check: () => Promise<boolean> | boolean, timeoutMs = 10_000): Promise<void> {
  const deadline = Date.now() + timeoutMs;
  while (!(await check())) {
    if (Date.now() > deadline) throw new Error('condition not reached');
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
}

describe('hal teleop', () => {
  let sim: SimulationHAL;
  let server: HalServer;
  let tty: FakeTty;

  beforeEach(async () => {
    // a served simulator, so the test can watch the robot the keys drive
    sim = new SimulationHAL({ clock: 'realtime', realtimeSpeed: 4 });
    await sim.initialize();
    server = await serveHal(sim, { port: 0 });
    tty = fakeTty();
  });
  afterEach(async () => {
    await server.close();
    await sim.cleanup();
  });

  const speed = async () => (await sim.locomotion.getPose()).velocity;

  it('drives with the keys, stops on space, quits on q and restores the terminal', async () => {
    const io = { ...captureIO(), stdin: tty };
    const run = runHal(['teleop', '--ws', server.url], io);
    await until(() => tty.isRaw);
    tty.type('w');
    await until(async () => (await speed()).linear > 0);
    tty.type(' ');
    await until(async () => (await speed()).linear === 0);
    tty.type('\x1b[D'); // left arrow: counter-clockwise in place
    await until(async () => (await speed()).angular > 0);
    tty.type('q');
    expect(await run).toBe(0);
    expect(tty.rawModes).toEqual([true, false]);
    expect((await speed()).angular).toBe(0); // quitting stopped the robot
    expect(io.stderr()).toContain('arrows/WASD drive');
    expect(io.stderr()).toMatch(/x \d+\.\d{3} m {2}y/); // the live pose line
    expect(io.stdout()).toMatch(/^final pose x 0\.\d{3} m/);
  });

  it('latches the e-stop on e, refuses driving while latched, and resets it on r', async () => {
    const io = { ...captureIO(), stdin: tty };
    const run = runHal(['--json', 'teleop', '--ws', server.url], io);
    await until(() => tty.isRaw);
    tty.type('e');
    await until(() => sim.safety.isEmergencyStopped() && io.jsonLines().length >= 1);
    tty.type('w');
    await until(() => io.jsonLines().length >= 2);
    tty.type('r');
    // the reset's own line: the robot is reset a moment before teleop has the reply, and a quit
    // in that moment ends the session without waiting for it
    await until(() => !sim.safety.isEmergencyStopped() && io.jsonLines().length >= 3);
    tty.type('q');
    expect(await run).toBe(0);
    const lines = io.jsonLines() as {
      key?: string;
      result?: { success: boolean; code?: string };
    }[];
    expect(lines.slice(0, 3).map((l) => [l.key, l.result?.success, l.result?.code])).toEqual([
      ['estop', true, undefined],
      ['forward', false, 'EMERGENCY_STOPPED'],
      ['reset', true, undefined],
    ]);
    expect((await sim.locomotion.getPose()).position.x).toBe(0);
    expect(tty.rawModes).toEqual([true, false]);
  });

  it('restores the terminal and stops the robot when it is interrupted by a signal', async () => {
    const io = { ...captureIO(), stdin: tty };
    const run = runHal(['teleop', '--ws', server.url], io);
    await until(() => tty.isRaw);
    tty.type('d');
    await until(async () => (await speed()).angular < 0);
    io.abort();
    expect(await run).toBe(0);
    expect(tty.rawModes).toEqual([true, false]);
    expect((await speed()).angular).toBe(0);
  });

  it('restores the terminal when the robot goes away mid-session', async () => {
    const io = { ...captureIO(), stdin: tty };
    const run = runHal(['teleop', '--ws', server.url], io);
    await until(() => tty.isRaw);
    await server.close(); // the link drops: the next key's call fails
    tty.type('w');
    tty.end();
    const code = await run;
    expect(tty.rawModes).toEqual([true, false]);
    expect(tty.isRaw).toBe(false);
    expect(code).toBe(1);
    expect(io.stderr()).toContain('hal: NOT_CONNECTED');
  });

  it('drives the embedded simulator (--sim) and reports the final pose as JSON', async () => {
    const io = { ...captureIO(), stdin: tty };
    const run = runHal(['--json', 'teleop', '--sim', '--time-scale', '10'], io);
    await until(() => tty.isRaw);
    tty.type('\x1b[A'); // up arrow
    await until(() => io.jsonLines().length >= 1);
    await new Promise((resolve) => setTimeout(resolve, 200));
    tty.type('q');
    expect(await run).toBe(0);
    const last = io.jsonLines().at(-1) as {
      event: string;
      keys: string[];
      pose: { position: { x: number } };
    };
    expect(last.event).toBe('ended');
    expect(last.keys).toEqual(['forward']);
    expect(last.pose.position.x).toBeGreaterThan(0);
    expect(tty.rawModes).toEqual([true, false]);
  });

  it('refuses clearly, before connecting, when stdin is not a terminal', async () => {
    const io = captureIO(); // no stdin
    expect(await runHal(['teleop', '--udp', '127.0.0.1:9'], io)).toBe(2);
    expect(io.stderr()).toContain('hal teleop reads the keyboard: run it in a terminal');
    const piped = { ...captureIO(), stdin: Object.assign(fakeTty(), { isTTY: false as const }) };
    expect(await runHal(['teleop', '--sim'], piped as never)).toBe(2);
  });
});
