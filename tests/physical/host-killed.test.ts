// The host process killed (SIGKILL) in the middle of an endless drive: nothing on the host side
// can send a stop any more, so only the robot's host timeout can end the motion. Timed on the
// robot's own clock, as any program on the network can read it (get_status).
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { endHostDuringDrive } from './host-kill.js';
import { stopAllHostProcesses } from './host-process.js';
import { probeStatus } from './robot-probe.js';

afterAll(async () => {
  await stopAllHostProcesses();
  await stopAllEmulators();
});

const HOST_TIMEOUT_MS = 500;

describe('a host process killed during an endless drive', () => {
  it('has the robot stop its motors within the host timeout plus 50 ms of the kill, by the robot clock', async () => {
    const emulator = await startEmulator({ hostTimeoutMs: HOST_TIMEOUT_MS, pty: false });
    try {
      // several host timeouts of driving, kept alive by the host's heartbeats alone
      const run = await endHostDuringDrive(emulator, {
        driveMs: 4 * HOST_TIMEOUT_MS,
        signal: 'SIGKILL',
      });
      const { status } = run;
      expect(status.running).toBe(false);
      expect(status.move_outcome).toBe('host_timeout');
      expect(status.safety.coils_on).toBe(false);
      expect(status.safety.trips).toBe(1);
      expect(status.safety.last_trip?.reason).toBe('host_timeout');
      // the robot dates the stop itself; its emulator log says the same
      const stoppedRobotMs = status.safety.last_trip!.uptime_ms;
      expect(run.finished['outcome']).toBe('host_timeout');
      expect(Math.abs(run.finishedRobotMs - stoppedRobotMs)).toBeLessThanOrEqual(1);

      // the drive ran until the host died ...
      expect(stoppedRobotMs - run.startedRobotMs).toBeGreaterThan(4 * HOST_TIMEOUT_MS);
      expect(stoppedRobotMs).toBeGreaterThan(run.killedRobotMs - 5);
      // ... and stopped within the host timeout plus 50 ms of the kill
      expect(stoppedRobotMs - run.killedRobotMs).toBeLessThanOrEqual(HOST_TIMEOUT_MS + 50);

      // and stayed stopped
      await new Promise((resolve) => setTimeout(resolve, 200));
      const later = await probeStatus(emulator.udpPort);
      expect(later.status.left_steps).toBe(status.left_steps);
      expect(later.status.right_steps).toBe(status.right_steps);
      expect(later.status.safety.trips).toBe(1);
    } finally {
      await emulator.stop();
    }
  });
});
