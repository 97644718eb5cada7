import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';
import { SimulationHAL, World } from '@hal/simulation';
import type { FleetMember } from './members.js';
import type { SteppedScheduler } from './scheduler.js';

/** `count` simulated robots in one world, on the manual clock, `spacingM` apart along y. */
export async function simFleet(
  count: number,
  options: { world?: World; spacingM?: number; prefix?: string } = {},
): Promise<{ world: World; members: FleetMember[]; hals: SimulationHAL[] }> {
  const world = options.world ?? new World();
  const spacing = options.spacingM ?? 0.3;
  const hals: SimulationHAL[] = [];
  const members: FleetMember[] = [];
  for (let i = 0; i < count; i++) {
    const id = `${options.prefix ?? 'r'}${i}`;
    const hal = new SimulationHAL({
      world,
      clock: 'manual',
      deviceId: id,
      start: { x: 0, y: i * spacing, yaw: 0 },
    });
    await hal.initialize();
    hals.push(hal);
    members.push({ id, hal });
  }
  return { world, members, hals };
}

/** A member whose `method` never answers: its calls hang (the fleet must not). */
export function hangingMember(
  id: string,
  base: HardwareAbstractionLayer,
  method: 'moveForward' | 'emergencyStop',
): FleetMember {
  const never = (): Promise<HALToolResult> => new Promise<HALToolResult>(() => undefined);
  const hal: HardwareAbstractionLayer = {
    mode: base.mode,
    locomotion:
      method === 'moveForward' ? { ...base.locomotion, moveForward: never } : base.locomotion,
    vision: base.vision,
    communication: base.communication,
    safety:
      method === 'emergencyStop'
        ? {
            emergencyStop: never,
            isEmergencyStopped: () => base.safety.isEmergencyStopped(),
            resetEmergencyStop: () => base.safety.resetEmergencyStop(),
            getSafetyStatus: () => base.safety.getSafetyStatus(),
          }
        : base.safety,
    initialize: () => base.initialize(),
    cleanup: () => base.cleanup(),
    isReady: () => base.isReady(),
    getDeviceInfo: () => base.getDeviceInfo(),
  };
  return { id, hal };
}

/** Lets pending promise callbacks and I/O run. */
export function flush(): Promise<void> {
  return new Promise((resolve) => setImmediate(resolve));
}

/**
 * Steps the world and the fleet's scheduler together, `stepMs` of simulated time at a time,
 * until `done()` or `maxMs` of simulated time. Returns whether `done()` became true.
 */
export async function stepUntil(
  world: World,
  scheduler: SteppedScheduler,
  done: () => boolean,
  maxMs: number,
  stepMs = 20,
): Promise<boolean> {
  const endUs = world.nowUs + maxMs * 1000;
  while (!done()) {
    if (world.nowUs >= endUs) return false;
    world.advance(stepMs * 1000);
    scheduler.advanceTo(world.nowUs / 1000);
    await flush();
  }
  return true;
}
