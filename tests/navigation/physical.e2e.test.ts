// The navigation bridge through PhysicalHAL against the emulated robot (the firmware's own core,
// built by `bash firmware/scripts/test.sh`) over UDP, on a clock 20 times real time. The
// emulated robot has no world: the known map is the bridge's only knowledge, and the same map and
// goal are run through SimulationHAL to compare where the two robots end up.
import { GoalSeekingProvider, NavigationBridge, OccupancyGrid } from '@hal/navigation';
import type { NavigationOutcome } from '@hal/navigation';
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL, World } from '@hal/simulation';
import type { WorldMapInput } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterAll, describe, expect, it } from 'vitest';
import { LONGEST_HOST_TIMEOUT_MS, startEmulator, stopAllEmulators } from '../physical/emulator.js';

const TIME_SCALE = 20;
afterAll(stopAllEmulators);

/** A box between the start (the origin, facing +x) and the goal. */
const map = {
  name: 'one box',
  arena: { width: 5, height: 5 },
  obstacles: [{ kind: 'box' as const, x: 0.5, y: 0, width: 0.3, depth: 0.6 }],
  starts: [{ x: 0, y: 0, yaw: 0 }],
} satisfies WorldMapInput;
const goal = { x: 1.0, y: 0.1 };

async function navigate(hal: HardwareAbstractionLayer): Promise<NavigationOutcome> {
  const bridge = new NavigationBridge({
    hal,
    provider: new GoalSeekingProvider(),
    grid: OccupancyGrid.fromMap(map),
    // The emulated robot has no range sensors; leave the simulated ones out too, so both runs
    // decide from the same knowledge.
    rangeSensors: false,
    maxCycles: 60,
  });
  return bridge.run(goal);
}

describe('NavigationBridge through PhysicalHAL to the emulated robot', () => {
  it('reaches a goal round a known obstacle, and ends where SimulationHAL ends', async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      pty: false,
      hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS, // not a test of the timeout
    });
    const physical = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-nav',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    let real: NavigationOutcome;
    try {
      await physical.initialize();
      real = await navigate(physical);
    } finally {
      await physical.cleanup();
      await emulator.stop();
    }
    expect(real.message).toMatch(/^reached/);
    expect(real.status).toBe('reached');
    // It went round the box (x 0.35..0.65, y -0.3..0.3), keeping the robot's radius off it.
    for (const p of real.trajectory) {
      const inside = p.x > 0.35 - 0.07 && p.x < 0.65 + 0.07 && Math.abs(p.y) < 0.3 + 0.07;
      expect(inside).toBe(false);
    }
    expect(await emulator.waitFor((e) => e.event === 'move_finished')).toBeDefined();

    const world = new World({ map });
    const simulated = new SimulationHAL({ world, clock: 'fast' });
    await simulated.initialize();
    const sim = await navigate(simulated);
    await simulated.cleanup();
    expect(sim.status).toBe('reached');
    // The same commands on the same firmware math: the same route, the same end.
    expect(sim.cycles).toBe(real.cycles);
    const a = real.finalPose;
    const b = sim.finalPose;
    expect(Math.hypot((a?.x ?? 0) - (b?.x ?? 9), (a?.y ?? 0) - (b?.y ?? 9))).toBeLessThan(0.01);
  });
});
