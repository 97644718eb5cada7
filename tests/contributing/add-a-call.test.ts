// CONTRIBUTING.md, "Add a HAL call", done once in the process: a call's entry in an extended call
// table, its subsystem method written the way RobotHAL writes its own (through a HalBoundary over
// that table, with the robot's existing commands on the world's binding), and the tool list and
// executor that get it from the table with no other edit. The other consumers of an extended
// table (serveHal and RemoteHAL, the NATS gateway and NatsHAL, HybridHAL, the fleet) are walked
// through by tests/call-table/extended-call.test.ts.
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { z } from 'zod';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor, halTools } from '@hal/tools';
import { HAL_CALL_TABLE, HalBoundary, findCall } from '@hal/types';
import type { CallName, CallSpec, CallTable, HALToolResult } from '@hal/types';

const root = fileURLToPath(new URL('../../', import.meta.url));

// Step 1: the call's entry (in the repository: a row of CALLS in call-table.ts).
/** Turn left and back `times` times by `degrees`: a motion made of the robot's own commands. */
const SHIMMY: CallSpec = {
  name: 'shimmy',
  subsystem: 'locomotion',
  method: 'shimmy',
  kind: 'motion',
  lane: 'queue',
  controllerOnly: true,
  cached: false,
  params: ['times', 'degrees'],
  paramsSchema: () =>
    z.object({
      times: z.number().int().min(1).max(3).describe('How many times, 1..3'),
      degrees: z.number().gt(0).max(30).describe('How far each way, degrees, at most 30'),
    }),
  data: z.looseObject({ shimmies: z.number(), yaw: z.number() }),
  tool: { name: 'shimmy', summary: 'Turn left and back in place, to show it heard you.' },
};
const TABLE: CallTable = [...HAL_CALL_TABLE, SHIMMY];

// Step 2: the subsystem method. RobotHAL writes each call as `boundary.call(name, args, body)`
// in packages/runtime/src/robot-hal/; here a subclass does the same over the extended table.
// The body uses RobotPort commands the robot already understands (step 3 is not needed).
class ShimmyingHAL extends SimulationHAL {
  readonly #calls = new HalBoundary({
    mode: 'simulation',
    config: () => this.binding.config(),
    isEmergencyStopped: () => this.binding.isEmergencyStopped(),
    isReady: () => this.isReady(),
    now: () => this.binding.now(),
    calls: TABLE,
  });

  constructor() {
    super();
    Object.assign(this.locomotion, {
      shimmy: (times: number, degrees: number): Promise<HALToolResult> =>
        // the built-in CallName type lists the built-in table; the boundary reads the extended one
        this.#calls.call('shimmy' as CallName, { times, degrees }, async (p) => {
          const { times: n, degrees: d } = p as unknown as { times: number; degrees: number };
          for (let i = 0; i < n; i += 1) {
            await this.binding.motion({ kind: 'rotate', degrees: d });
            await this.binding.motion({ kind: 'rotate', degrees: -d });
          }
          return { shimmies: n, yaw: this.binding.pose().rotation.yaw };
        }),
    });
  }
}

describe('a new call (CONTRIBUTING.md: Add a HAL call)', () => {
  it('names files that exist, in the order the recipe gives them', () => {
    for (const file of [
      'packages/types/src/schemas/call-table.ts',
      'packages/types/src/interfaces.ts',
      'packages/runtime/src/robot-hal/locomotion.ts',
      'packages/types/src/robot-port.ts',
      'packages/simulation/src/hal/world-binding.ts',
      'packages/physical/src/hal/wire-binding.ts',
      'packages/types/src/testing/contract-samples.ts',
      'packages/types/src/testing/contract-boundary.ts',
      'tests/properties/hal-calls.ts',
      'tests/call-table/extended-call.test.ts',
    ]) {
      expect(existsSync(`${root}${file}`), file).toBe(true);
    }
    expect(findCall('shimmy')).toBeUndefined();
    expect(findCall('shimmy', TABLE)).toBe(SHIMMY);
  });

  it('is a tool the executor runs on the simulated robot, with the table as its schema', async () => {
    const hal = new ShimmyingHAL();
    await hal.initialize();
    try {
      const tools = halTools(hal, { calls: TABLE });
      const tool = tools.find((t) => t.name === 'shimmy');
      expect(tool).toMatchObject({ call: 'shimmy', motion: true });
      expect(Object.keys(tool?.inputSchema.properties ?? {}).sort()).toEqual(['degrees', 'times']);
      const executor = createToolExecutor(hal, { tools, calls: TABLE });
      const done = await executor.execute({
        name: 'shimmy',
        arguments: { times: 2, degrees: 20 },
      });
      expect(done.isError, JSON.stringify(done)).toBe(false);
      // four turns of the simulated robot, each the firmware's rotate_deg: back where it started
      const pose = await hal.locomotion.getPose();
      expect(Math.abs(pose.rotation.yaw)).toBeLessThan(0.01);
    } finally {
      await hal.cleanup();
    }
  });

  it("gets the boundary's rules from its entry: range, e-stop gate, readiness", async () => {
    const hal = new ShimmyingHAL();
    const shimmy = (times: number, degrees: number) =>
      (
        hal.locomotion as unknown as {
          shimmy(t: number, d: number): Promise<HALToolResult>;
        }
      ).shimmy(times, degrees);
    expect(await shimmy(1, 10)).toMatchObject({ success: false, code: 'NOT_READY' });
    await hal.initialize();
    try {
      expect(await shimmy(1, 45)).toMatchObject({ success: false, code: 'RANGE_EXCEEDED' });
      expect(await shimmy(1.5, 10)).toMatchObject({ success: false, code: 'INVALID_PARAMETER' });
      await hal.safety.emergencyStop('test');
      // kind "motion": refused while the stop is latched, like every motion of the table
      expect(await shimmy(1, 10)).toMatchObject({ success: false, code: 'EMERGENCY_STOPPED' });
      await hal.safety.resetEmergencyStop();
      expect(await shimmy(1, 10)).toMatchObject({ success: true, data: { shimmies: 1 } });
    } finally {
      await hal.cleanup();
    }
  });
});
