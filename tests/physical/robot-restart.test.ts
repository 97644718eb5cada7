// The robot restarted in the middle of a session (power cut, brown-out, watchdog): the emulator
// is killed and a new one starts on the same UDP port. The host must notice, open a new session,
// latch the new robot's e-stop again if the host had set one, and never replay a move into it.
import { PhysicalHAL } from '@hal/physical';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import type { Emulator } from './emulator.js';
import { probeStatus } from './robot-probe.js';
import { startSerialFaultRelay } from './serial-fault-relay.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 5;

const moves = (emulator: Emulator) => emulator.events.filter((e) => e.event === 'move_started');

function connect(port: number): PhysicalHAL {
  return new PhysicalHAL(
    {
      mode: 'physical',
      deviceId: 'cube-restarted',
      connection: { type: 'wifi', host: '127.0.0.1', udpPort: port },
    },
    { timeScale: TIME_SCALE, reconnectIntervalMs: 100 },
  );
}

/** Kills the robot and starts a fresh one on the same port, as a reboot would. */
async function restart(emulator: Emulator): Promise<Emulator> {
  await emulator.kill();
  return startEmulator({ timeScale: TIME_SCALE, udpPort: emulator.udpPort, pty: false });
}

describe('a robot that restarts in the middle of a session', () => {
  it('is e-stopped again by the host that had e-stopped it, in a new session, and moves nothing until reset', async () => {
    const first = await startEmulator({ timeScale: TIME_SCALE, pty: false });
    const hal = connect(first.udpPort);
    let second: Emulator | undefined;
    try {
      await hal.initialize();
      const stop = await hal.safety.emergencyStop('operator pressed stop');
      expect(stop.success).toBe(true);
      second = await restart(first);
      // the new robot starts unlatched; the host must notice and latch it again
      expect((await probeStatus(second.udpPort)).status.safety.estop).toBe(false);
      const trip = await second.waitFor(
        (e) => e.event === 'trip' && e['reason'] === 'estop_command',
        15_000,
      );
      expect(trip['estop']).toBe(true);
      await expect.poll(() => hal.linkState, { timeout: 5000 }).toBe('connected');
      const { status } = await probeStatus(second.udpPort);
      expect(status.safety.estop).toBe(true);
      expect(status.safety['estop_reason']).toBe('operator pressed stop');

      const refused = await hal.locomotion.moveForward(2);
      expect(refused.success).toBe(false);
      expect(refused.code).toBe('EMERGENCY_STOPPED');
      expect(moves(second)).toEqual([]);

      // an explicit reset clears it, and then one move is one move
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect(hal.safety.isEmergencyStopped()).toBe(false);
      expect((await hal.locomotion.moveForward(2)).success).toBe(true);
      expect(moves(second)).toHaveLength(1);
      expect((await probeStatus(second.udpPort)).status.left_steps).toBe(434);
    } finally {
      await hal.cleanup();
      await second?.stop();
      await first.stop();
    }
  });

  it('replays neither the move it was running nor a move sent while it was down into the new robot', async () => {
    const first = await startEmulator({ timeScale: TIME_SCALE, pty: false });
    const hal = connect(first.udpPort);
    let second: Emulator | undefined;
    let third: Emulator | undefined;
    try {
      await hal.initialize();
      // a long move, cut by the restart
      const running = hal.locomotion.moveForward(30);
      await first.waitFor((e) => e.event === 'move_started', 10_000);
      second = await restart(first);
      const cut = await running;
      expect(cut.success).toBe(false);
      // whether the host first heard of the new session or of the new robot's status
      expect(['NOT_CONNECTED', 'INTERRUPTED']).toContain(cut.code);
      expect(cut.error).toMatch(/restarted/);
      await expect.poll(() => hal.linkState, { timeout: 10_000 }).toBe('connected');
      expect(moves(second)).toEqual([]);
      const afterCut = await probeStatus(second.udpPort);
      expect(afterCut.status.move_id).toBe(0);
      expect(afterCut.status.left_steps).toBe(0);

      // a move sent while the robot is down reaches the new robot only as a retry of the old
      // session, which it refuses
      await second.kill();
      const lost = hal.locomotion.moveForward(3);
      await new Promise((resolve) => setTimeout(resolve, 150));
      third = await startEmulator({ timeScale: TIME_SCALE, udpPort: first.udpPort, pty: false });
      const refused = await lost;
      expect(refused.success).toBe(false);
      await expect.poll(() => hal.linkState, { timeout: 10_000 }).toBe('connected');
      expect(moves(third)).toEqual([]);
      expect((await probeStatus(third.udpPort)).status.move_id).toBe(0);

      // the host asks for one move: the new robot makes exactly one
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
      expect(moves(third)).toHaveLength(1);
      expect((await probeStatus(third.udpPort)).status.left_steps).toBe(217);
    } finally {
      await hal.cleanup();
      await third?.stop();
      await second?.stop();
      await first.stop();
    }
  });

  it('over serial, behind a port that stays, is e-stopped again and runs none of the old moves', async () => {
    const first = await startEmulator({ timeScale: TIME_SCALE });
    const clean = { garbage: 0, bitFlip: 0, duplicate: 0 };
    const relay = await startSerialFaultRelay({
      robotPty: first.pty,
      seed: 1,
      toRobot: clean,
      toHost: clean,
    });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-restarted-serial',
        connection: { type: 'serial', port: relay.path },
      },
      { timeScale: TIME_SCALE, reconnectIntervalMs: 100 },
    );
    let second: Emulator | undefined;
    try {
      await hal.initialize();
      const running = hal.locomotion.moveForward(30);
      await first.waitFor((e) => e.event === 'move_started', 10_000);
      expect((await hal.safety.emergencyStop('stop before reboot')).success).toBe(true);
      expect((await running).code).toBe('EMERGENCY_STOPPED');

      await first.kill();
      second = await startEmulator({ timeScale: TIME_SCALE, pty: true });
      await relay.replaceRobot(second.pty);
      await second.waitFor((e) => e.event === 'trip' && e['reason'] === 'estop_command', 15_000);
      await expect.poll(() => hal.linkState, { timeout: 5000 }).toBe('connected');
      const status = await hal.refreshStatus();
      expect(status.safety.estop).toBe(true);
      expect(status.safety.estop_reason).toBe('stop before reboot');
      expect(status.move_id).toBe(0);
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect(moves(second)).toEqual([]);

      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
      expect((await hal.locomotion.moveForward(1)).success).toBe(true);
      expect(moves(second)).toHaveLength(1);
      expect((await hal.refreshStatus()).left_steps).toBe(217);
    } finally {
      await hal.cleanup();
      await relay.close();
      await second?.stop();
      await first.stop();
    }
  });
});
