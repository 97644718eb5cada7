// Teleop from a viewer: Foxglove's Teleop panel publishes geometry_msgs/Twist (linear.x m/s,
// angular.z rad/s) at its rate while a button is held. Each message becomes one bounded drive
// (the wheels' powers for `holdMs`), so a viewer that stops publishing, or vanishes, leaves the
// robot stopped within `holdMs`. The drive goes through the leash (its caps, geofence and
// approval) and whatever guard the served HAL has; a refusal is answered, never driven.
import { HalError, maxLinearSpeedMPerS } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer, RobotConfig } from '@hal/types';

/** The wheels' powers (-255..255) of a Twist, or a clear error for a message that is none. */
export function powersOfTwist(
  message: unknown,
  config: RobotConfig,
): { left: number; right: number } {
  const m = message as { linear?: { x?: unknown }; angular?: { z?: unknown } } | null;
  const v = m?.linear?.x ?? 0;
  const w = m?.angular?.z ?? 0;
  if (
    typeof v !== 'number' ||
    typeof w !== 'number' ||
    !Number.isFinite(v) ||
    !Number.isFinite(w)
  ) {
    throw new HalError(
      'INVALID_PARAMETER',
      'a teleop message is a geometry_msgs/Twist: {"linear":{"x":m/s},"angular":{"z":rad/s}}',
      { details: { parameter: 'twist' } },
    );
  }
  const half = config.wheelBaseCm / 200;
  const top = maxLinearSpeedMPerS(config);
  // beyond the robot's top speed a wheel runs at full power (the leash judges the speed asked)
  const power = (speed: number) => Math.max(-255, Math.min(255, Math.round((speed / top) * 255)));
  return { left: power(v - w * half), right: power(v + w * half) };
}

/** One teleop message's outcome: driven, or refused with the HAL's or the leash's words. */
export type TeleopOutcome = { driven: true } | { driven: false; code: string; error: string };

/** Drives one message's powers for `holdMs` on `hal` (the leashed one). Never rejects. */
export async function driveOnce(
  hal: HardwareAbstractionLayer,
  powers: { left: number; right: number },
  holdMs: number,
): Promise<TeleopOutcome> {
  let result: HALToolResult;
  try {
    result = await hal.locomotion.drive(powers.left, powers.right, holdMs);
  } catch (error) {
    return { driven: false, code: 'HARDWARE_ERROR', error: String(error) };
  }
  // INTERRUPTED: the next message (or a stop) took over from this one, as teleop does
  if (result.success || result.code === 'INTERRUPTED') return { driven: true };
  const detailCode = (result as { details?: { code?: unknown } }).details?.code;
  const code =
    result.code ?? (typeof detailCode === 'string' ? detailCode : undefined) ?? 'REFUSED';
  return { driven: false, code, error: result.error ?? code };
}
