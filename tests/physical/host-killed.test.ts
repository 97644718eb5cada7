// The host process killed (SIGKILL) in the middle of an endless drive: nothing on the host side
// can send a stop any more, so only the robot's host timeout can end the motion. Timed on the
// robot's own clock, as any program on the network can read it (get_status).
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { startHostProcess, stopAllHostProcesses } from './host-process.js';
import { probeStatus } from './robot-probe.js';

afterAll(async () => {
  await stopAllHostProcesses();
  await stopAllEmulators();
});

const HOST_TIMEOUT_MS = 500;
const sleep = (ms: number) => new Promise<void>((resolve) => setTimeout(resolve, ms));

describe('a host process killed during an endless drive', () => {
  it('has the robot stop its motors within the host timeout plus 50 ms of the kill, by the robot clock', async () => {
    const emulator = await startEmulator({ hostTimeoutMs: HOST_TIMEOUT_MS, pty: false });
    try {
      // the robot's clock against ours (both monotonic, the robot at time scale 1): robot uptime
      // at our time t is at least offset + t, since the uptime was read before the reply arrived
      const before = await probeStatus(emulator.udpPort);
      const offset = before.status.uptime_ms - before.receivedAt;

      const host = startHostProcess('endless-drive.ts', [String(emulator.udpPort)]);
      const driving = await host.waitFor((e) => e.event === 'driving', 30_000);
      expect(driving['success']).toBe(true);
      // let it drive for several host timeouts, kept alive by the host's heartbeats alone
      await sleep(4 * HOST_TIMEOUT_MS);
      const killedAt = performance.now();
      await host.kill('SIGKILL');
      const killedRobotMs = offset + killedAt;

      const finished = await emulator.waitFor(
        (e) => e.event === 'move_finished' && e['kind'] === 'drive',
        5000,
      );
      const after = await probeStatus(emulator.udpPort);
      const { status } = after;
      expect(status.running).toBe(false);
      expect(status.move_outcome).toBe('host_timeout');
      expect(status.safety.coils_on).toBe(false);
      expect(status.safety.last_trip?.reason).toBe('host_timeout');
      const stoppedRobotMs = status.safety.last_trip!.uptime_ms;
      // the motion ended where the trip was recorded (the emulator's log says the same)
      expect(finished['outcome']).toBe('host_timeout');
      expect(Math.abs(Number(finished['t_ms']) - stoppedRobotMs)).toBeLessThanOrEqual(1);

      // the drive ran until the host died: the heartbeats alone kept it going past the timeout
      const started = emulator.events.find(
        (e) => e.event === 'move_started' && e['kind'] === 'drive',
      )!;
      expect(stoppedRobotMs - Number(started['t_ms'])).toBeGreaterThan(4 * HOST_TIMEOUT_MS);
      expect(stoppedRobotMs).toBeGreaterThan(killedRobotMs - 5);
      // ... and stopped within the host timeout plus 50 ms of the kill
      expect(stoppedRobotMs - killedRobotMs).toBeLessThanOrEqual(HOST_TIMEOUT_MS + 50);

      // and stayed stopped
      await sleep(200);
      const later = await probeStatus(emulator.udpPort);
      expect(later.status.left_steps).toBe(status.left_steps);
      expect(later.status.right_steps).toBe(status.right_steps);
      expect(later.status.safety.trips).toBe(1);
    } finally {
      await emulator.stop();
    }
  });
});
