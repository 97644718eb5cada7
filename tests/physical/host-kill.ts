// Starts a host process (processes/endless-drive.ts) that drives the robot endlessly, lets it
// drive, then ends it, and dates the kill and the motors' stop on the robot's clock. Used by the
// host-killed test and bench/host-kill.bench.ts.
import type { Emulator, EmulatorEvent } from './emulator.js';
import { startHostProcess } from './host-process.js';
import { probeStatus } from './robot-probe.js';
import type { Probe } from './robot-probe.js';

export interface KillDuringDrive {
  /** The robot's uptime when the drive started, ms. */
  startedRobotMs: number;
  /** The robot's uptime when the host was ended, ms (a lower bound; see below). */
  killedRobotMs: number;
  /** The robot's uptime when the drive ended (its emulator log), ms. */
  finishedRobotMs: number;
  /** The emulator's move_finished event of the drive. */
  finished: EmulatorEvent;
  /** The robot's status right after the drive ended. */
  status: Probe['status'];
}

const sleep = (ms: number) => new Promise<void>((resolve) => setTimeout(resolve, ms));

/**
 * `signal` SIGKILL: the host dies with no chance to act. SIGTERM: the host catches it, calls
 * `hal.cleanup()` (which stops the motors) and exits. The robot must run at time scale 1.
 */
export async function endHostDuringDrive(
  emulator: Emulator,
  options: { driveMs: number; signal: 'SIGKILL' | 'SIGTERM' },
): Promise<KillDuringDrive> {
  // the robot's clock against ours (both monotonic): robot uptime at our time t is at least
  // offset + t, since the uptime was read before its reply arrived
  const before = await probeStatus(emulator.udpPort);
  const offset = before.status.uptime_ms - before.receivedAt;
  const finishedBefore = emulator.events.filter((e) => e.event === 'move_finished').length;

  const host = startHostProcess('endless-drive.ts', [String(emulator.udpPort)]);
  try {
    const driving = await host.waitFor((e) => e.event === 'driving', 30_000);
    if (driving['success'] !== true) throw new Error(`drive failed: ${String(driving['error'])}`);
    const started = await emulator.waitFor(
      (e) =>
        e.event === 'move_started' &&
        e['move_id'] === (driving['data'] as { moveId: number }).moveId,
    );
    await sleep(options.driveMs);
    const killedAt = performance.now();
    await host.kill(options.signal);
    const finished = await emulator.waitFor(
      (e) =>
        e.event === 'move_finished' &&
        e['move_id'] === started['move_id'] &&
        emulator.events.indexOf(e) >= finishedBefore,
      15_000,
    );
    const { status } = await probeStatus(emulator.udpPort);
    return {
      startedRobotMs: Number(started['t_ms']),
      killedRobotMs: offset + killedAt,
      finishedRobotMs: Number(finished['t_ms']),
      finished,
      status,
    };
  } finally {
    await host.kill();
  }
}
