// On the board the step interrupt runs whatever the loop is doing, and a request is read as it
// comes. The emulator makes its steps between passes of its loop, and on a loaded machine it can
// be kept off the CPU for longer than a move lasts. These tests stop it (SIGSTOP) with requests
// waiting, and hold that each is handled as at the time the kernel received it: a status asked
// after the move's end counts every step (the fault that made a golden exchange fail under
// load), and an e-stop sent early in the stall latches then, not when the process runs again.
import { setTimeout as sleep } from 'node:timers/promises';
import { afterAll, describe, expect, it } from 'vitest';
import type { Emulator } from './emulator.js';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { robotClock } from './estop-trial.js';
import { probeStatus, seedRequest } from './robot-probe.js';

afterAll(stopAllEmulators);

/**
 * Runs `during` with the emulator stopped, and always lets it run again. What `during` gives is
 * wrapped, so a reply still to come is not awaited while the emulator cannot send it.
 */
async function whileStopped<T>(emulator: Emulator, during: () => Promise<T>): Promise<T> {
  process.kill(emulator.pid, 'SIGSTOP');
  try {
    return await during();
  } finally {
    process.kill(emulator.pid, 'SIGCONT');
  }
}

describe('the emulator kept off the CPU', () => {
  it('answers a status asked after the move ended with every step made and the move done', async () => {
    const emulator = await startEmulator({ pty: false });
    try {
      const move = await seedRequest(emulator.udpPort, {
        cmd: 'move_steps',
        left: 100,
        right: -100,
        speed: 800,
      });
      expect(move).toMatchObject({ ok: true, move_id: 1 });
      const durationMs = move['duration_ms'] as number;
      // stopped for the whole move and more, but for less than the host timeout (2 s)
      expect(durationMs + 400).toBeLessThan(2000);
      const { asked } = await whileStopped(emulator, async () => {
        await sleep(durationMs + 200);
        const pending = probeStatus(emulator.udpPort, 5000);
        await sleep(200);
        return { asked: pending };
      });
      const { status } = await asked;
      expect(status).toMatchObject({
        left_steps: 100,
        right_steps: -100,
        running: false,
        move_id: 1,
        move_outcome: 'done',
        safety: { trips: 0, coils_on: false },
      });
    } finally {
      await emulator.stop();
    }
  });

  it('latches an e-stop sent early in the stall at the time it came, not when it was read', async () => {
    const emulator = await startEmulator({ pty: false });
    const now = robotClock(emulator);
    try {
      const move = await seedRequest(emulator.udpPort, {
        cmd: 'move_steps',
        left: 4000,
        right: 4000,
        speed: 1000,
      });
      expect(move).toMatchObject({ ok: true });
      let sentUs = 0;
      let resumedUs = 0;
      const { answer } = await whileStopped(emulator, async () => {
        sentUs = now();
        const pending = seedRequest(emulator.udpPort, { cmd: 'estop', reason: 'stall' });
        await sleep(500);
        resumedUs = now();
        return { answer: pending };
      });
      const reply = await answer;
      expect(reply).toMatchObject({ ok: true });
      const estopUs = Number(reply['estop_us']);
      expect(estopUs).toBeGreaterThanOrEqual(sentUs);
      expect(estopUs).toBeLessThan(resumedUs);
      const status = await probeStatus(emulator.udpPort);
      expect(status.status).toMatchObject({ running: false, move_outcome: 'estop' });
    } finally {
      await emulator.stop();
    }
  });
});
