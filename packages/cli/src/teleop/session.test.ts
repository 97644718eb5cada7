import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { fakeTty } from '../testing/fake-tty.js';
import { runTeleop } from './session.js';
import { withStatusLine } from './status-line.js';

/** The simulator, except that drive() never answers (a stalled link). */
function stalledDrive(sim: SimulationHAL): HardwareAbstractionLayer & { drives: number } {
  const hal = {
    drives: 0,
    mode: sim.mode,
    locomotion: {
      ...sim.locomotion,
      drive: () => {
        hal.drives += 1;
        return new Promise<never>(() => undefined);
      },
    },
    vision: sim.vision,
    communication: sim.communication,
    safety: sim.safety,
    initialize: () => sim.initialize(),
    cleanup: () => sim.cleanup(),
    isReady: () => sim.isReady(),
    getDeviceInfo: () => sim.getDeviceInfo(),
  };
  return hal;
}

describe('a teleop session', () => {
  let sim: SimulationHAL;
  beforeEach(async () => {
    sim = new SimulationHAL();
    await sim.initialize();
  });
  afterEach(() => sim.cleanup());

  it('sends the e-stop at once, drops queued drive keys, and quits, while a call hangs', async () => {
    const hal = stalledDrive(sim);
    const tty = fakeTty();
    const io = captureIO();
    const session = runTeleop(
      hal,
      tty,
      withStatusLine(io),
      { json: true },
      { power: 100, turnPower: 100 },
    );
    const deadline = Date.now() + 5000;
    tty.type('w'); // hangs
    while (hal.drives === 0 && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 10));
    }
    tty.type('aaaa'); // queued behind it
    tty.type('e'); // not queued: latches now
    while (!sim.safety.isEmergencyStopped() && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 10));
    }
    expect(sim.safety.isEmergencyStopped()).toBe(true);
    tty.type('q');
    const summary = await session;
    expect(summary.keys).toEqual(['forward', 'estop']); // the four queued turns were dropped
    expect(hal.drives).toBe(1);
    expect(summary.emergencyStopped).toBe(true);
    expect(io.jsonLines()).toEqual([
      { key: 'estop', result: expect.objectContaining({ success: true }) },
    ]);
  });

  it('ends when its input ends', async () => {
    const tty = fakeTty();
    const io = captureIO();
    const session = runTeleop(
      sim,
      tty,
      withStatusLine(io),
      { json: false },
      { power: 100, turnPower: 100 },
    );
    tty.end();
    const summary = await session;
    expect(summary.keys).toEqual([]);
    expect(io.stderr()).toContain('teleop ended; the robot was stopped');
  });

  it('prints a warning that comes while the pose line is shown on a line of its own', async () => {
    const tty = fakeTty();
    const io = captureIO();
    const lineIO = withStatusLine(io);
    let poses = 0;
    const warning = 'warn hal:physical link lost\n';
    const hal = {
      ...sim,
      mode: sim.mode,
      locomotion: {
        ...sim.locomotion,
        getPose: async () => {
          poses += 1;
          // the HAL's logger writes through the same io, as it does in `hal teleop`
          if (poses === 2) lineIO.err(warning);
          return await sim.locomotion.getPose();
        },
      },
      vision: sim.vision,
      communication: sim.communication,
      safety: sim.safety,
      initialize: () => sim.initialize(),
      cleanup: () => sim.cleanup(),
      isReady: () => sim.isReady(),
      getDeviceInfo: () => sim.getDeviceInfo(),
    };
    const session = runTeleop(hal, tty, lineIO, { json: false }, { power: 100, turnPower: 100 });
    const deadline = Date.now() + 5000;
    while (poses < 3 && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 10));
    }
    tty.end();
    await session;
    // what the terminal shows: each \r\x1b[K starts the line again
    const shown = io
      .stderr()
      .split('\n')
      .map((line) => line.split('\r\x1b[K').at(-1) ?? '');
    expect(shown).toContain('warn hal:physical link lost');
    expect(shown.filter((line) => line.includes('warn')).every((l) => !/x \d/.test(l))).toBe(true);
  });

  it('never says the robot was stopped when the stop was not acknowledged', async () => {
    const tty = fakeTty();
    const io = captureIO();
    const hal = {
      ...sim,
      mode: sim.mode,
      locomotion: {
        ...sim.locomotion,
        stop: async () => ({
          success: false,
          code: 'NOT_CONNECTED' as const,
          error: 'the robot could not be told to stop',
          timestamp: Date.now(),
          mode: sim.mode,
        }),
      },
      vision: sim.vision,
      communication: sim.communication,
      safety: sim.safety,
      initialize: () => sim.initialize(),
      cleanup: () => sim.cleanup(),
      isReady: () => sim.isReady(),
      getDeviceInfo: () => sim.getDeviceInfo(),
    };
    const session = runTeleop(
      hal,
      tty,
      withStatusLine(io),
      { json: false },
      {
        power: 100,
        turnPower: 100,
      },
    );
    tty.end();
    const summary = await session;
    expect(summary.stop).toEqual({
      stopped: false,
      code: 'NOT_CONNECTED',
      error: 'the robot could not be told to stop',
    });
    expect(io.stderr()).not.toContain('the robot was stopped');
    expect(io.stderr()).toContain('teleop ended; the robot did not confirm the stop');
  });
});
