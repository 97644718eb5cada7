// The soak: 10,000 commands through PhysicalHAL, in a host process of their own, over UDP and over
// the emulator's pseudo-terminal. No reply may be lost, the robot's counters must match, and
// neither process may grow: the host's heap after a full GC and both resident sizes are compared
// between the end of the warm-up and the end of the run. The figures are in bench/soak.bench.ts.
import { describe, expect, it } from 'vitest';
import { runSoak } from './soak.js';
import type { SoakLink } from './soak.js';

const COUNT = 10_000;
const MB = 1024 * 1024;

describe('the soak, 10,000 commands through PhysicalHAL', () => {
  for (const link of ['udp', 'serial'] as SoakLink[]) {
    it(`loses no reply over ${link} and leaves the memory of the host and the robot flat`, async () => {
      const r = await runSoak({ link, count: COUNT, timeScale: 10, maxSeconds: 150 });
      expect(r.commands).toBe(COUNT);
      expect(r.failures).toEqual([]);
      expect(r.failed).toBe(0);
      expect(r.timeouts).toBe(0);
      expect(r.trips).toBe(0);
      expect(r.moveStarted).toBe(r.motions);
      expect(r.robot.moveId).toBe(r.motions);
      expect(r.robot.left).toBe(r.expected.left);
      expect(r.robot.right).toBe(r.expected.right);
      expect(r.host.gc).toBe(true);
      // ~8,000 requests after warm-up: even 250 bytes kept per request would show
      expect(r.host.heapEnd).toBeLessThan(r.host.heapStart + 2 * MB);
      expect(r.host.rssEnd).toBeLessThan(r.host.rssStart + 40 * MB);
      // the firmware core never allocates
      expect(r.emulator.rssEnd).toBeLessThanOrEqual(r.emulator.rssStart + 1 * MB);
    }, 200_000);
  }
});
