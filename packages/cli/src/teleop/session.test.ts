import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { captureIO } from '../capture-io.fixture.js';
import { fakeTty } from './fake-tty.fixture.js';
import { runTeleop } from './session.js';

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
    const session = runTeleop(hal, tty, io, { json: true }, { power: 100, turnPower: 100 });
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
    const session = runTeleop(sim, tty, io, { json: false }, { power: 100, turnPower: 100 });
    tty.end();
    const summary = await session;
    expect(summary.keys).toEqual([]);
    expect(io.stderr()).toContain('teleop ended; the robot was stopped');
  });
});
