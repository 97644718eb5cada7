// The devices seen on NATS, for `hal test hal --all`: every device that announces its
// capabilities on the spec's subject (`hal.v1.system.capability.announce`, the default device)
// or on a fleet device's (`hal.v1.dev.{device}.system.capability.announce`).
import { CapabilityAnnouncementSchema, subjectFor } from '@hal/nats';
import { buildSubject, delay, HalError } from '@hal/types';
import type { NatsConnection } from '@nats-io/transport-node';
import { inspect } from './inspect.js';

/** A device seen announcing itself, and how to address it. */
export interface SeenDevice {
  /** The id in its announcements' envelope (the sender). */
  deviceId: string;
  /**
   * The id to pass as `device` to runCompliance: the device's own when it announced on its fleet
   * subject; undefined when it was seen only on the spec's bare subject (the default device).
   */
  address: string | undefined;
  caps: string[];
}

/** How long `hal test hal --all` listens by default, ms: longer than the 5 s announce interval. */
export const DEFAULT_SEEN_WINDOW_MS = 6000;

/**
 * Listens for capability announcements for `windowMs` and returns every device seen, sorted by
 * id; a default device that announces on both subjects is one device, addressed by its id.
 * An announcement that is not a valid envelope with a capability payload is not a device.
 */
export async function devicesSeenOnNats(options: {
  connection: NatsConnection;
  windowMs?: number;
}): Promise<SeenDevice[]> {
  const windowMs = options.windowMs ?? DEFAULT_SEEN_WINDOW_MS;
  if (!Number.isFinite(windowMs) || windowMs < 1 || windowMs > 600_000) {
    throw new HalError('RANGE_EXCEEDED', `"windowMs" must be 1..600000, got ${windowMs}`);
  }
  const nc = options.connection;
  const seen = new Map<string, SeenDevice>();
  const note = (data: Uint8Array, address: string | undefined) => {
    const message = inspect(data, CapabilityAnnouncementSchema, address);
    if (message.envelope === undefined || message.payload === undefined) return;
    if (message.issues.some((issue) => issue.startsWith('device_id is'))) return;
    const deviceId = message.envelope.device_id;
    const known = seen.get(deviceId);
    if (known === undefined || (known.address === undefined && address !== undefined)) {
      seen.set(deviceId, { deviceId, address, caps: message.payload.caps });
    }
  };
  const fleet = buildSubject(
    { device: '*', domain: 'system', type: 'capability', action: 'announce' },
    { wildcards: true },
  );
  const subs = [
    nc.subscribe(subjectFor('capabilityAnnounce'), {
      callback: (error, msg) => {
        if (error === null) note(msg.data, undefined);
      },
    }),
    nc.subscribe(fleet, {
      callback: (error, msg) => {
        if (error === null) note(msg.data, msg.subject.split('.')[3]);
      },
    }),
  ];
  try {
    await nc.flush();
    await delay(windowMs);
  } finally {
    for (const sub of subs) sub.unsubscribe();
  }
  return [...seen.values()].sort((a, b) => a.deviceId.localeCompare(b.deviceId));
}
