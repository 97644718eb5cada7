// The e-stop against the real emulator over real UDP, on a clean and on a lossy link, with a
// robot driving and a get_status stuck retrying: the stop is never queued behind it, the robot
// stops and latches, the running move resolves EMERGENCY_STOPPED, and few steps follow the call
// (measured on the robot's clock). The tests hold orders and the robot's own consistency, which a
// loaded machine's delays do not change; the latency figures are in bench/estop.bench.ts.
import { PhysicalHAL } from '@hal/physical';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import type { Faults } from './fault-proxy.js';
import { startFaultProxy } from './fault-proxy.js';
import { estopTrial, robotClock, setAcceleration, TRIAL_ACCELERATION } from './estop-trial.js';

afterAll(stopAllEmulators);

const TRIALS = 8;

async function rig(faults: Faults) {
  // the default host timeout: the HAL resends every 500 ms, as it would on a real robot
  const emulator = await startEmulator({ pty: false });
  await setAcceleration(emulator.udpPort, TRIAL_ACCELERATION);
  const proxy = await startFaultProxy({
    robotPort: emulator.udpPort,
    seed: 20261130,
    toRobot: faults,
    toHost: faults,
  });
  const hal = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'cube-estop',
    connection: { type: 'wifi', host: '127.0.0.1', udpPort: proxy.port },
  });
  await hal.initialize();
  return { emulator, proxy, hal, now: robotClock(emulator) };
}

describe('emergencyStop() against the emulator over UDP', () => {
  for (const [link, faults] of [
    ['a clean link', {}],
    ['a link losing 30% both ways', { drop: 0.3 }],
  ] as Array<[string, Faults]>) {
    it(`stops a driving robot at once on ${link}, however the pending status request fares`, async () => {
      const { emulator, proxy, hal, now } = await rig(faults);
      try {
        for (let i = 0; i < TRIALS; i++) {
          const trial = await estopTrial({
            hal,
            emulator,
            proxy,
            now,
            path: 'lane',
            runMs: 30 + 10 * i,
            lostReplies: 2,
          });
          expect(trial.estop.success, JSON.stringify(trial.estop)).toBe(true);
          expect(trial.move.code, JSON.stringify(trial.move)).toBe('EMERGENCY_STOPPED');
          expect(trial.estop.data?.['moveOutcome']).toBe('estop');
          expect(trial.robotLatencyMs).toBeGreaterThanOrEqual(0);
          // the stuck get_status holds the request queue for two 500 ms resends: the stop is
          // answered while it still waits
          expect(trial.stoppedBeforeStatus).toBe(true);
          // at 1024 steps/s, 1.024 steps per ms after the call (and one already due)
          expect(trial.stepsAfterCall).toBeLessThanOrEqual(
            Math.ceil(trial.robotLatencyMs * 1.024) + 1,
          );
          expect(trial.estop.data?.['leftSteps']).toBeGreaterThan(0);
        }
        // latched, and nothing moved after the last stop
        const finished = await emulator.waitForCount((e) => e.event === 'move_finished', TRIALS);
        expect(finished).toHaveLength(TRIALS);
        expect(finished.every((e) => e['outcome'] === 'estop')).toBe(true);
        expect(emulator.events.filter((e) => e.event === 'move_started')).toHaveLength(TRIALS);
      } finally {
        await hal.cleanup();
        await proxy.close();
        await emulator.stop();
      }
    }, 60_000);
  }

  it('measures a trial the same when it abandons the stuck request and goes on with a fresh session', async () => {
    const { emulator, proxy, hal: first, now } = await rig({});
    const open = async () => {
      const fresh = new PhysicalHAL({
        mode: 'physical',
        deviceId: 'cube-estop',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: proxy.port },
      });
      await fresh.initialize();
      return fresh;
    };
    let hal = first;
    try {
      for (let i = 0; i < 4; i++) {
        const path = i % 2 === 0 ? 'lane' : 'queued';
        const before = hal;
        const trial = await estopTrial({
          hal,
          emulator,
          proxy,
          now,
          path,
          runMs: 30,
          lostReplies: 2,
          reopen: open,
          faults: { drop: 0.3 },
        });
        hal = trial.hal;
        expect(trial.move.code, JSON.stringify(trial.move)).toBe('EMERGENCY_STOPPED');
        expect(trial.robotLatencyMs).toBeGreaterThanOrEqual(0);
        // a lane trial leaves the stuck request (two 500 ms resends) behind; a queued one waits
        if (path === 'lane') {
          expect(trial.stoppedBeforeStatus).toBe(true);
          expect(hal).not.toBe(before);
          expect(before.isReady()).toBe(false);
        } else {
          expect(trial.stoppedBeforeStatus).toBe(false);
          expect(trial.robotLatencyMs).toBeGreaterThan(900);
          expect(hal).toBe(before);
        }
        expect(hal.isReady()).toBe(true);
        expect(hal.safety.isEmergencyStopped()).toBe(false);
      }
      expect(emulator.events.filter((e) => e.event === 'move_started')).toHaveLength(4);
    } finally {
      await hal.cleanup();
      await proxy.close();
      await emulator.stop();
    }
  }, 60_000);

  it('latches the robot and reports a sanitized reason, whatever the reason was', async () => {
    const { emulator, proxy, hal } = await rig({});
    try {
      const result = await hal.safety.emergencyStop(`${'\u0001'.repeat(200)}${'é'.repeat(80)}`);
      expect(result.success).toBe(true);
      expect(result.data?.['reason']).toBe('é'.repeat(31));
      const status = await hal.refreshStatus();
      expect(status.safety.estop).toBe(true);
      expect(status.safety.estop_reason).toBe('é'.repeat(31));
      expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
      expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
    } finally {
      await hal.cleanup();
      await proxy.close();
      await emulator.stop();
    }
  });
});
