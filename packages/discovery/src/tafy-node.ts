// A NATS gateway as the Tafy HAL spec's driver announces itself: DNS-SD `_tafynode._tcp` with
// `device_id` and `caps` in the TXT record, on the NATS server's port (where the node is reached).
// The cube itself keeps `_hal-cube._udp` (service.ts).
import { HalError, parseCapability, raceTimer } from '@hal/types';
import { z } from 'zod';
import { openMdns } from './mdns-socket.js';
import type { MdnsOptions } from './mdns-socket.js';
import { publishService } from './publish-service.js';
import { MAX_TXT_ENTRY_BYTES } from './service.js';

/** The spec's service name (without the underscore bonjour-service adds) and transport. */
export const TAFY_NODE_SERVICE = 'tafynode';
export const TAFY_NODE_PROTOCOL = 'tcp';
export const TAFY_NODE_TYPE = `_${TAFY_NODE_SERVICE}._${TAFY_NODE_PROTOCOL}`;

export interface TafyNodeAnnouncement {
  /** The device id: the node's subjects are `hal.v1.dev.{deviceId}...`. */
  deviceId: string;
  /** Capability strings, `{domain}.{type}:v{major}.{minor}[:metadata]`. */
  caps: readonly string[];
  /** The TCP port where the node is reached: the NATS server's. */
  port: number;
  /** The NATS server URL(s) the node serves on, published as `nats` (ours, beside the spec's). */
  servers?: readonly string[];
  /** Instance name; default the device id. */
  name?: string;
  mdns?: MdnsOptions;
  /** How long to wait for the first announcement to go out, ms. Default 5000. */
  timeoutMs?: number;
}

/**
 * The TXT entries: `device_id`, `caps` (comma-separated; continued in `caps1`, `caps2`, ... when
 * one entry would pass 255 bytes, as the cube's record does), and `nats` when servers are given.
 */
export function tafyNodeTxt(node: TafyNodeAnnouncement): Record<string, string> {
  const txt: Record<string, string> = { txtvers: '1', device_id: node.deviceId };
  const parts: string[] = [];
  let current = '';
  for (const cap of node.caps) {
    parseCapability(cap); // INVALID_PARAMETER for a malformed capability string
    const next = current === '' ? cap : `${current},${cap}`;
    const key = parts.length === 0 ? 'caps' : `caps${parts.length}`;
    if (Buffer.byteLength(`${key}=${next}`) > MAX_TXT_ENTRY_BYTES && current !== '') {
      parts.push(current);
      current = cap;
    } else current = next;
  }
  parts.push(current);
  parts.forEach((part, i) => (txt[i === 0 ? 'caps' : `caps${i}`] = part));
  if (node.servers !== undefined && node.servers.length > 0) txt['nats'] = node.servers.join(',');
  const over = Object.entries(txt).find(([k, v]) => Buffer.byteLength(`${k}=${v}`) > 255);
  if (over !== undefined) {
    throw new HalError('INVALID_PARAMETER', `TXT entry "${over[0]}" is over 255 bytes`);
  }
  return txt;
}

export interface TafyNodeAnnouncer {
  name: string;
  txt: Record<string, string>;
  /** Sends the goodbye and closes the socket. */
  stop(): Promise<void>;
}

/**
 * Announces a NATS node as `_tafynode._tcp` and resolves once the first announcement went out.
 * INVALID_PARAMETER for a bad device id, capability or port; NOT_CONNECTED when the mDNS socket
 * fails; TIMEOUT when nothing went out in `timeoutMs`.
 */
export async function announceTafyNode(node: TafyNodeAnnouncement): Promise<TafyNodeAnnouncer> {
  if (!/^[A-Za-z0-9_-]+$/.test(node.deviceId)) {
    throw new HalError('INVALID_PARAMETER', `"deviceId" is not a device id: "${node.deviceId}"`);
  }
  if (!Number.isInteger(node.port) || node.port < 1 || node.port > 65_535) {
    throw new HalError('INVALID_PARAMETER', `"port" must be 1..65535, got ${node.port}`);
  }
  const txt = tafyNodeTxt(node);
  const name = node.name ?? node.deviceId;
  const timeoutMs = node.timeoutMs ?? 5000;
  const published = await publishService({
    name,
    type: TAFY_NODE_SERVICE,
    protocol: TAFY_NODE_PROTOCOL,
    port: node.port,
    txt,
    timeoutMs,
    mdns: node.mdns,
  });
  return { ...published, txt };
}

const TxtSchema = z
  .object({ device_id: z.string().min(1), caps: z.string() })
  .catchall(z.unknown());

/** A node found on the network. */
export interface FoundTafyNode {
  deviceId: string;
  caps: string[];
  port: number;
  addresses: string[];
  servers: string[];
}

/** Browses `_tafynode._tcp` for `timeoutMs` (1..60000); a record without device_id and caps is skipped. */
export async function discoverTafyNodes(
  options: { timeoutMs?: number; mdns?: MdnsOptions } = {},
): Promise<FoundTafyNode[]> {
  const timeoutMs = options.timeoutMs ?? 3000;
  if (!Number.isFinite(timeoutMs) || timeoutMs < 1 || timeoutMs > 60_000) {
    throw new HalError('RANGE_EXCEEDED', `"timeoutMs" must be 1..60000, got ${timeoutMs}`);
  }
  const mdns = openMdns(options.mdns);
  const found = new Map<string, FoundTafyNode>();
  const browser = mdns.bonjour.find({ type: TAFY_NODE_SERVICE, protocol: TAFY_NODE_PROTOCOL });
  browser.on('up', (service) => {
    const txt = TxtSchema.safeParse(service.txt);
    if (!txt.success) return;
    const caps: string[] = [];
    for (let i = 0; ; i += 1) {
      const part = txt.data[i === 0 ? 'caps' : `caps${i}`];
      if (typeof part !== 'string') break;
      if (part !== '') caps.push(...part.split(','));
    }
    const nats = txt.data['nats'];
    found.set(txt.data.device_id, {
      deviceId: txt.data.device_id,
      caps,
      port: service.port,
      addresses: service.addresses ?? [],
      servers: typeof nats === 'string' && nats !== '' ? nats.split(',') : [],
    });
  });
  try {
    // listens for `timeoutMs`; a failed socket ends it early
    await raceTimer(mdns.failed, timeoutMs, () => undefined);
  } finally {
    browser.stop();
    await mdns.close();
  }
  return [...found.values()];
}
