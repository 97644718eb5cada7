import { argsFromObject, callMethod, forwardCalls, invokeSpec, objectFromArgs } from '@hal/types';
import type {
  CallName,
  CallSpec,
  CallTable,
  ForwardedSubsystems,
  HALToolResult,
  SafetyInterface,
} from '@hal/types';
import type { HybridContext } from './context.js';

/**
 * Besides every locomotion command, the calls the twin runs too, so a twin's UI shows them (the
 * LED). Speech, sound and logs go to the physical robot alone.
 */
const SHOWN_ON_TWIN: ReadonlySet<string> = new Set(['setLED']);

function onTwin(spec: CallSpec): boolean {
  return spec.subsystem === 'locomotion' || SHOWN_ON_TWIN.has(spec.name);
}

/**
 * The subsystems of a HybridHAL, one method per call of `table`:
 * - every motion runs on both robots; the pose is the physical robot's. A `moveTo` target is a
 *   point of the physical robot's frame, carried into the twin's frame for the twin;
 * - sensing is the physical robot's alone: what it lacks fails as it fails there
 *   (NOT_IMPLEMENTED), never filled in from the twin's simulated sensors;
 * - speech, sound and logs go to the physical robot; the LED to both;
 * - safety is `safety` (safety.ts), which latches both.
 * Every call is guarded and validated once by the hybrid's boundary.
 */
export function createSubsystems(
  ctx: HybridContext,
  safety: SafetyInterface,
  table: CallTable,
): ForwardedSubsystems {
  const { physical: p, twin: t } = ctx;
  const forward = (spec: CallSpec, args: unknown[]): unknown => {
    const name = spec.name as CallName; // an extended table's call is validated by its own schema
    const named = objectFromArgs(spec, args);
    const on = (hal: typeof p) => (a: object) =>
      invokeSpec(
        hal,
        spec,
        argsFromObject(spec, a as Record<string, unknown>),
      ) as Promise<HALToolResult>;
    switch (spec.kind) {
      case 'value':
        return ctx.read(name, named, on(p));
      case 'void':
        return ctx.notify(name, named, (a) => {
          callMethod(p, spec, argsFromObject(spec, a as Record<string, unknown>));
        });
      default:
        return ctx.run(name, named, on(p), onTwin(spec) ? on(t) : undefined);
    }
  };
  return forwardCalls(
    forward,
    {
      moveTo: (x: number, y: number, z: number, speed?: number) =>
        ctx.run(
          'moveTo',
          { x, y, z, speed },
          (a) => p.locomotion.moveTo(a.x, a.y, a.z, a.speed),
          (a) => {
            const target = ctx.twinPoint(a.x, a.y);
            return t.locomotion.moveTo(target.x, target.y, a.z, a.speed);
          },
        ),
      emergencyStop: safety.emergencyStop,
      resetEmergencyStop: safety.resetEmergencyStop,
      isEmergencyStopped: safety.isEmergencyStopped,
      getSafetyStatus: safety.getSafetyStatus,
    },
    table,
  );
}
