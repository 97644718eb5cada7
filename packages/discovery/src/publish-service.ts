// One DNS-SD publication, as both announcers make it (the emulated cube's `_hal-cube._udp` and a
// NATS gateway's `_tafynode._tcp`): published without a probe, resolved once the first
// announcement went out, and stopped with a best-effort goodbye before the socket closes.
import { deadline, HalError } from '@hal/types';
import { openMdns } from './mdns-socket.js';
import type { MdnsOptions } from './mdns-socket.js';

export interface PublishedService {
  /** The instance name published. */
  name: string;
  /** Sends the goodbye (TTL 0, best effort for 1 s) and closes the socket. */
  stop(): Promise<void>;
}

/**
 * Publishes `type`.`protocol` with `txt` on `port`. Rejects with NOT_CONNECTED when the mDNS
 * socket fails, TIMEOUT when nothing went out in `timeoutMs`; the socket is closed either way.
 */
export async function publishService(service: {
  name: string;
  type: string;
  protocol: 'tcp' | 'udp';
  port: number;
  txt: Record<string, string>;
  timeoutMs: number;
  mdns?: MdnsOptions | undefined;
}): Promise<PublishedService> {
  const mdns = openMdns(service.mdns);
  // No probe: bonjour-service reports a name conflict on the console only. Device ids are the
  // robots' unique addresses; the callers check one is free before announcing it.
  const published = mdns.bonjour.publish({
    name: service.name,
    type: service.type,
    protocol: service.protocol,
    port: service.port,
    txt: service.txt,
    probe: false,
  });
  try {
    await deadline(
      Promise.race([
        mdns.failed,
        new Promise<void>((resolve) => published.once('up', () => resolve())),
      ]),
      service.timeoutMs,
      () =>
        new HalError('TIMEOUT', `the announcement did not go out in ${service.timeoutMs} ms`, {
          details: { timeoutMs: service.timeoutMs },
        }),
    );
  } catch (error) {
    await mdns.close();
    throw error;
  }
  let stopped: Promise<void> | undefined;
  return {
    name: service.name,
    stop: () =>
      (stopped ??= new Promise<void>((resolve) => {
        const done = setTimeout(resolve, 1000); // the goodbye is best effort
        published.stop?.(() => {
          clearTimeout(done);
          resolve();
        });
      }).then(() => mdns.close())),
  };
}
