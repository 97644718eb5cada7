// `hal teleop` and `hal drive` when the robot dies mid-drive (the emulated robot killed with
// SIGKILL, as a power cut would): the pose the host keeps predicting is marked as predicted, no
// stop is claimed that the robot did not acknowledge, and the command says that the robot's own
// host timeout is what stops it, and exits non-zero.
import { runHal } from '@hal/cli';
import { afterEach, describe, expect, it } from 'vitest';
import { fakeTty } from '@hal/cli/testing';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';

const TIME_SCALE = 4;
const HOST_TIMEOUT_MS = 2000;

afterEach(stopAllEmulators);

async function emulated(): Promise<{ emulator: Emulator; udp: string[] }> {
  const emulator = await startEmulator({
    timeScale: TIME_SCALE,
    hostTimeoutMs: HOST_TIMEOUT_MS,
    pty: false,
  });
  return {
    emulator,
    udp: ['--udp', `127.0.0.1:${emulator.udpPort}`, '--time-scale', String(TIME_SCALE)],
  };
}

const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/** Resolves `promise`, or rejects once `ms` have passed: the command must not hang. */
async function within<T>(promise: Promise<T>, ms: number, what: string): Promise<T> {
  let timer: NodeJS.Timeout | undefined;
  const late = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} did not end within ${ms} ms`)), ms);
  });
  try {
    return await Promise.race([promise, late]);
  } finally {
    clearTimeout(timer);
  }
}

/** The x of every pose printed in `text` ("x 0.123 m"). */
const xs = (text: string): number[] =>
  [...text.matchAll(/x (-?\d+\.\d{3}) m/g)].map((m) => Number(m[1]));

describe('a robot that dies mid-drive', () => {
  it('teleop marks the pose predicted, claims no stop, names the host timeout and fails', async () => {
    const { emulator, udp } = await emulated();
    const tty = fakeTty();
    const io = { ...captureIO(), stdin: tty };
    const run = runHal(['teleop', ...udp], io);
    const deadline = Date.now() + 20_000;
    while (!tty.isRaw && Date.now() < deadline) await sleep(20);
    tty.type('w');
    await emulator.waitFor((e) => e.event === 'move_started', 10_000);
    await sleep(300);
    await emulator.kill();
    await sleep(1500);
    const lost = io.stderr();
    tty.type('q');
    // the link is known dead: quitting does not wait out the full retry budget of a stop
    const code = await within(run, 3000, 'teleop after q');

    expect(code).not.toBe(0);
    const err = io.stderr();
    expect(err).not.toContain('the robot was stopped');
    expect(err).toContain('could not be told to stop');
    expect(err).toContain(`host timeout (${HOST_TIMEOUT_MS} ms)`);
    // the pose line after the robot died says it is a prediction
    const lastLine = lost.split('\r').at(-1) ?? '';
    expect(lastLine).toMatch(/x \d+\.\d{3} m .*predicted/);
    expect(io.stdout()).toMatch(/^final pose x \d+\.\d{3} m .*predicted/);
  });

  it('drive never shows the planned end as reached, and fails naming the host timeout', async () => {
    const { emulator, udp } = await emulated();
    const io = captureIO();
    // 0.3 m at 4.71 cm/s: 6.4 s of robot time, 1.6 s at this time scale
    const run = runHal(['drive', 'forward', '0.3', ...udp], io);
    await emulator.waitFor((e) => e.event === 'move_started', 10_000);
    await sleep(400);
    await emulator.kill();
    const code = await within(run, 20_000, 'drive');

    expect(code).toBe(1);
    const err = io.stderr();
    expect(err).toMatch(/hal: NOT_CONNECTED: .*could not be told to stop/);
    expect(err).toContain(`host timeout (${HOST_TIMEOUT_MS} ms)`);
    const poses = xs(err);
    expect(poses.length).toBeGreaterThan(0);
    // killed ~1.6 s of robot time in (about 0.07 m): the prediction stops where the robot's
    // host timeout would have stopped it at the latest, far short of 0.300 m
    expect(Math.max(...poses)).toBeLessThan(0.25);
    const lines = err.split('\n').filter((l) => /x -?\d+\.\d{3} m/.test(l));
    expect(lines.at(-1)).toContain('predicted');
  });

  it('drive wheels does not claim the stop on Ctrl-C once the robot is dead', async () => {
    const { emulator, udp } = await emulated();
    const io = captureIO();
    const run = runHal(['drive', 'wheels', '200', '200', ...udp], io); // until Ctrl-C
    await emulator.waitFor((e) => e.event === 'move_started', 10_000);
    await emulator.kill();
    io.abort();
    const code = await within(run, 10_000, 'drive wheels after Ctrl-C');

    expect(code).not.toBe(0);
    const err = io.stderr();
    expect(err).not.toMatch(/stopped on Ctrl-C|the robot was stopped/);
    expect(io.stdout()).not.toContain('stopped on Ctrl-C');
    expect(err).toContain('could not be told to stop');
    expect(err).toContain(`host timeout (${HOST_TIMEOUT_MS} ms)`);
  });
});
