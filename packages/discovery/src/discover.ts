// Finding robots: browse `_hal-cube._udp` for a while, check every answer's TXT record, and return
// the robots that announced themselves correctly. A malformed record is skipped and logged.
import type { Service } from 'bonjour-service';
import { HalError, scoped, silentLogger } from '@hal/types';
import type { Logger } from '@hal/types';
import { isOnThisMachine } from './local-address.js';
import { openMdns } from './mdns-socket.js';
import type { MdnsOptions } from './mdns-socket.js';
import { SERVICE_NAME, SERVICE_PROTOCOL } from './service.js';
import { parseAnnouncementTxt } from './txt-record.js';
import type { AnnouncedAuth } from './txt-record.js';

/** A robot found on the network. */
export interface DiscoveredRobot {
  deviceId: string;
  /** The DNS-SD instance name (the board announces its device id). */
  name: string;
  /** The host name its service record points to, e.g. `cube-a1b2c3.local`. */
  host: string;
  /** Its addresses from the announcement (or, when it gave none, the packet's source). */
  addresses: string[];
  /** UDP port of the wire protocol. */
  port: number;
  /** The wire protocol version, e.g. `1.1`. */
  protocolVersion: string;
  /** How it authenticates: `hmac-sha256` needs the robot's key; `none` takes anyone. */
  auth: AnnouncedAuth;
  /** True when commanding it needs its pre-shared key. */
  requiresKey: boolean;
  /** Capability strings, `{domain}.{type}:v{major}.{minor}[:metadata]`. */
  capabilities: string[];
  /** True when it was announced from this machine (an emulator): reach it over 127.0.0.1. */
  onThisMachine: boolean;
}

export interface DiscoverOptions {
  /** How long to listen, ms (1..60000). Default 3000. */
  timeoutMs?: number;
  /** Where skipped records are reported (namespace `hal:discovery`). Default: nowhere. */
  logger?: Logger;
  /** Which interface and port mDNS uses. */
  mdns?: MdnsOptions;
  /** Stops listening early. */
  signal?: AbortSignal;
  /** Called as each robot is found (before the timeout ends). */
  onFound?: (robot: DiscoveredRobot) => void;
}

export const DEFAULT_DISCOVERY_TIMEOUT_MS = 3000;
const MAX_TIMEOUT_MS = 60_000;

function checkTimeout(timeoutMs: number): void {
  if (!Number.isFinite(timeoutMs) || timeoutMs < 1 || timeoutMs > MAX_TIMEOUT_MS) {
    throw new HalError(
      Number.isFinite(timeoutMs) ? 'RANGE_EXCEEDED' : 'INVALID_PARAMETER',
      `"timeoutMs" must be a number of ms in 1..${MAX_TIMEOUT_MS}, got ${String(timeoutMs)}`,
    );
  }
}

function toRobot(service: Service, logger: ReturnType<typeof scoped>): DiscoveredRobot | undefined {
  const parsed = parseAnnouncementTxt(service.txt ?? {});
  if (!parsed.ok) {
    logger.warn(`skipped "${service.name}": ${parsed.reason}`, {
      name: service.name,
      host: service.host,
      reason: parsed.reason,
    });
    return undefined;
  }
  if (!Number.isInteger(service.port) || service.port < 1 || service.port > 65_535) {
    logger.warn(`skipped "${service.name}": port ${String(service.port)} is not 1..65535`);
    return undefined;
  }
  const { announcement } = parsed;
  const announced = service.addresses ?? [];
  const addresses =
    announced.length > 0 ? [...announced] : service.referer ? [service.referer.address] : [];
  return {
    deviceId: announcement.deviceId,
    name: service.name,
    host: service.host,
    addresses,
    port: service.port,
    protocolVersion: announcement.protocolVersion,
    auth: announcement.auth,
    requiresKey: announcement.auth !== 'none',
    capabilities: announcement.capabilities,
    onThisMachine: isOnThisMachine(addresses),
  };
}

/**
 * Listens for robots for `timeoutMs` and resolves the ones found, one per device id (the latest
 * answer wins), sorted by device id. Never rejects for a bad announcement (it is logged and
 * skipped); rejects with NOT_CONNECTED when the mDNS socket cannot be opened.
 */
export async function discoverRobots(options: DiscoverOptions = {}): Promise<DiscoveredRobot[]> {
  const timeoutMs = options.timeoutMs ?? DEFAULT_DISCOVERY_TIMEOUT_MS;
  checkTimeout(timeoutMs);
  const logger = scoped(options.logger ?? silentLogger, 'hal:discovery');
  const found = new Map<string, DiscoveredRobot>();
  const mdns = openMdns(options.mdns);
  const browser = mdns.bonjour.find({ type: SERVICE_NAME, protocol: SERVICE_PROTOCOL });
  const onService = (service: Service) => {
    const robot = toRobot(service, logger);
    if (robot === undefined) return;
    found.set(robot.deviceId, robot);
    options.onFound?.(robot);
  };
  browser.on('up', onService);
  browser.on('txt-update', onService);
  let timer: NodeJS.Timeout | undefined;
  let onAbort: (() => void) | undefined;
  try {
    await Promise.race([
      mdns.failed,
      new Promise<void>((resolve) => {
        timer = setTimeout(resolve, timeoutMs);
        onAbort = () => resolve();
        if (options.signal?.aborted) resolve();
        options.signal?.addEventListener('abort', onAbort, { once: true });
      }),
    ]);
  } finally {
    clearTimeout(timer);
    if (onAbort) options.signal?.removeEventListener('abort', onAbort);
    browser.stop();
    await mdns.close();
  }
  return [...found.values()].sort((a, b) => a.deviceId.localeCompare(b.deviceId));
}

/**
 * Listens until the robot `deviceId` answers, and resolves it at once; rejects with NOT_FOUND when
 * it has not answered within `timeoutMs` (default 3000): TIMEOUT.
 */
export async function findRobot(
  deviceId: string,
  options: Omit<DiscoverOptions, 'onFound'> = {},
): Promise<DiscoveredRobot> {
  const stop = new AbortController();
  const outer = options.signal;
  const forward = () => stop.abort();
  outer?.addEventListener('abort', forward, { once: true });
  let match: DiscoveredRobot | undefined;
  try {
    await discoverRobots({
      ...options,
      signal: stop.signal,
      onFound: (robot) => {
        if (robot.deviceId !== deviceId) return;
        match = robot;
        stop.abort();
      },
    });
  } finally {
    outer?.removeEventListener('abort', forward);
  }
  if (match === undefined) {
    const ms = options.timeoutMs ?? DEFAULT_DISCOVERY_TIMEOUT_MS;
    throw new HalError('TIMEOUT', `no robot "${deviceId}" answered within ${ms} ms`, {
      details: { deviceId, timeoutMs: ms },
    });
  }
  return match;
}
