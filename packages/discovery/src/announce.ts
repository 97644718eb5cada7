// Announcing a robot that has no mDNS responder of its own (the emulator): publishes the TXT
// entries it printed, built by the firmware core, under `_hal-cube._udp` on its port.
import { HalError } from '@hal/types';
import type { MdnsOptions } from './mdns-socket.js';
import { publishService } from './publish-service.js';
import { SERVICE_NAME, SERVICE_PROTOCOL } from './service.js';
import { oversizeTxtEntry, parseAnnouncementTxt } from './txt-record.js';

export interface AnnounceOptions {
  /** The robot's UDP port. */
  port: number;
  /** The TXT entries, as the robot built them (the emulator's ready line, `mdns.txt`). */
  txt: Record<string, string>;
  /** Instance name; default the device id. */
  name?: string;
  mdns?: MdnsOptions;
  /** How long to wait for the first announcement to go out, ms. Default 5000. */
  timeoutMs?: number;
}

export interface Announcer {
  /** The instance name published. */
  name: string;
  /** Sends the goodbye (TTL 0) and closes the socket. */
  stop(): Promise<void>;
}

/**
 * Publishes a robot on this machine's addresses and resolves once the first announcement went
 * out. Refuses (INVALID_PARAMETER) a TXT record that discovery would skip, or an entry over 255
 * bytes; rejects with NOT_CONNECTED when the mDNS socket fails, TIMEOUT when nothing went out.
 */
export async function announceRobot(options: AnnounceOptions): Promise<Announcer> {
  const parsed = parseAnnouncementTxt(options.txt);
  if (!parsed.ok) {
    throw new HalError('INVALID_PARAMETER', `not a robot announcement: ${parsed.reason}`);
  }
  const oversize = oversizeTxtEntry(options.txt);
  if (oversize !== undefined) {
    throw new HalError('INVALID_PARAMETER', `TXT entry "${oversize}" is over 255 bytes`);
  }
  if (!Number.isInteger(options.port) || options.port < 1 || options.port > 65_535) {
    throw new HalError('INVALID_PARAMETER', `"port" must be 1..65535, got ${options.port}`);
  }
  const name = options.name ?? parsed.announcement.deviceId;
  const timeoutMs = options.timeoutMs ?? 5000;
  return publishService({
    name,
    type: SERVICE_NAME,
    protocol: SERVICE_PROTOCOL,
    port: options.port,
    txt: options.txt,
    timeoutMs,
    mdns: options.mdns,
  });
}
