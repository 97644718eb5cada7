// On the board the step interrupt runs whatever the loop is doing, so a reply always counts every
// step that fell due before the request. The emulator makes its steps between passes of its
// loop; on a loaded machine it can be kept off the CPU for longer than a move lasts. This holds
// that a request waiting when it wakes is answered with the steps due by then, not with the
// position from before it slept (the fault that made a golden exchange fail under load).
import { createSocket } from 'node:dgram';
import { setTimeout as sleep } from 'node:timers/promises';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { probeStatus } from './robot-probe.js';

afterAll(stopAllEmulators);

async function sendOnce(port: number, request: object): Promise<Record<string, unknown>> {
  const socket = createSocket('udp4');
  try {
    await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
    return await new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error('no reply from the emulator in 3 s')), 3000);
      socket.once('message', (message) => {
        clearTimeout(timer);
        resolve(JSON.parse(message.toString()) as Record<string, unknown>);
      });
      socket.send(JSON.stringify(request), port, '127.0.0.1');
    });
  } finally {
    socket.close();
  }
}

describe('the emulator kept off the CPU', () => {
  it('answers a request that waited for it with every step due, and the move ended', async () => {
    const emulator = await startEmulator({ pty: false });
    try {
      const move = await sendOnce(emulator.udpPort, {
        cmd: 'move_steps',
        left: 100,
        right: -100,
        speed: 800,
      });
      expect(move).toMatchObject({ ok: true, move_id: 1 });
      const durationMs = move['duration_ms'] as number;
      expect(durationMs).toBeGreaterThan(0);
      // Stopped for the whole move and more, but for less than the host timeout (2 s).
      process.kill(emulator.pid, 'SIGSTOP');
      let resumed = false;
      try {
        const stoppedFor = durationMs + 400;
        expect(stoppedFor).toBeLessThan(2000);
        const probe = probeStatus(emulator.udpPort, 5000);
        await sleep(stoppedFor);
        process.kill(emulator.pid, 'SIGCONT');
        resumed = true;
        const { status } = await probe;
        expect(status).toMatchObject({
          left_steps: 100,
          right_steps: -100,
          running: false,
          move_id: 1,
          move_outcome: 'done',
          safety: { trips: 0, coils_on: false },
        });
      } finally {
        if (!resumed) process.kill(emulator.pid, 'SIGCONT');
      }
    } finally {
      await emulator.stop();
    }
  });
});
