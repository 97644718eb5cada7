import { CapabilityAnnouncementSchema, decodeMessage } from '@hal/nats';
import type { NatsConnection } from '@nats-io/transport-node';
import { delay, DEVICE_SUBJECT_TOKEN, parseSubject } from '@hal/types';

/** A device heard announcing itself on NATS. */
export interface DiscoveredDevice {
  /** Its fleet address (`hal.v1.dev.{device}...`). */
  device: string;
  deviceType: string;
  mode: string;
  capabilities: string[];
  stateRateHz: number;
}

/**
 * Listens for `timeoutMs` to the capability announcements of every fleet device
 * (`hal.v1.dev.*.system.capability.announce`, repeated by each gateway every 5 s by default) and
 * returns the devices heard, sorted by id. Malformed announcements are skipped.
 */
export async function discoverNatsDevices(
  connection: NatsConnection,
  timeoutMs = 6000,
): Promise<DiscoveredDevice[]> {
  const found = new Map<string, DiscoveredDevice>();
  const subject = `hal.v1.${DEVICE_SUBJECT_TOKEN}.*.system.capability.announce`;
  const sub = connection.subscribe(subject, {
    callback: (error, msg) => {
      if (error !== null) return;
      try {
        const device = parseSubject(msg.subject).device;
        const payload = decodeMessage(msg.data, CapabilityAnnouncementSchema).payload;
        if (device === undefined) return;
        found.set(device, {
          device,
          deviceType: payload.device_type,
          mode: payload.mode,
          capabilities: [...payload.caps],
          stateRateHz: payload.state_rate_hz,
        });
      } catch {
        // not an announcement we can read: not a device we can drive
      }
    },
  });
  await delay(timeoutMs);
  sub.unsubscribe();
  return [...found.values()].sort((a, b) => a.device.localeCompare(b.device));
}
