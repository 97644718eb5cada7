import { HalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';

/** One robot of a fleet: its device id and the HAL that drives it. */
export interface FleetMember {
  /** Device id: letters, digits, "-" and "_" (the same rule as a HAL config's `deviceId`). */
  id: string;
  hal: HardwareAbstractionLayer;
}

const DEVICE_ID = /^[A-Za-z0-9_-]{1,64}$/;

/** Checks a device id; a bad one is an INVALID_PARAMETER HalError. */
export function checkDeviceId(id: unknown): string {
  if (typeof id !== 'string' || !DEVICE_ID.test(id)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `device ids are 1..64 of letters, digits, "-" and "_", got ${JSON.stringify(id) ?? String(id)}`,
      { details: { device: id } },
    );
  }
  return id;
}

/** Picks the members named by `devices` (all when undefined); an unknown id is an error. */
export function selectMembers(
  members: readonly FleetMember[],
  devices: readonly string[] | undefined,
): FleetMember[] {
  if (devices === undefined) return [...members];
  const byId = new Map(members.map((m) => [m.id, m]));
  const unknown = devices.filter((d) => !byId.has(d));
  if (unknown.length > 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `no fleet member ${unknown.map((d) => `"${d}"`).join(', ')} (members: ${[...byId.keys()].join(', ') || 'none'})`,
      { details: { unknown, members: [...byId.keys()] } },
    );
  }
  return [...new Set(devices)].map((d) => byId.get(d) as FleetMember);
}
