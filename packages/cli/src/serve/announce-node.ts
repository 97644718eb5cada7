// `hal serve --nats` announces its gateway as the spec's driver does: `_tafynode._tcp` with the
// device id and capabilities in the TXT record, on the NATS server's port. An mDNS failure (no
// multicast on this network) is reported and serving goes on: NATS does not need it.
import { announceTafyNode } from '@hal/discovery';
import type { TafyNodeAnnouncer } from '@hal/discovery';
import { errorMessage } from '@hal/types';

const NATS_DEFAULT_PORT = 4222;

/** The TCP port of a NATS server URL (`nats://host:4222`, `host:4222`, `host`). */
export function natsPort(server: string): number {
  const match = /:(\d+)\/?$/.exec(server.replace(/^[a-z]+:\/\//i, ''));
  const port = match === null ? NATS_DEFAULT_PORT : Number(match[1]);
  return port >= 1 && port <= 65_535 ? port : NATS_DEFAULT_PORT;
}

/** Announces the node; resolves to the announcer, or to the reason it could not be announced. */
export async function announceGateway(node: {
  deviceId: string;
  caps: readonly string[];
  servers: readonly string[];
}): Promise<TafyNodeAnnouncer | string> {
  try {
    return await announceTafyNode({
      deviceId: node.deviceId,
      caps: node.caps,
      port: natsPort(node.servers[0] ?? ''),
      servers: node.servers,
    });
  } catch (error) {
    return errorMessage(error);
  }
}
