import { HalError, errorMessage } from '@hal/types';
import { connect } from '@nats-io/transport-node';
import type { ConnectionOptions, NatsConnection } from '@nats-io/transport-node';

/** How to reach NATS: servers and credentials, passed through to nats.js. */
export interface NatsConnectOptions {
  /** e.g. `nats://127.0.0.1:4222`, or a list for a cluster. */
  servers: string | string[];
  /** User/password authentication. */
  user?: string;
  pass?: string;
  /** Token authentication. */
  token?: string;
  /** TLS: `{ caFile, certFile, keyFile }` as nats.js takes them; the server must be configured. */
  tls?: ConnectionOptions['tls'];
  /** A name shown in the server's connection list. */
  name?: string;
  /** Wait between reconnect attempts, ms. Default 250. */
  reconnectTimeWaitMs?: number;
}

/** Either an open connection (shared, not closed by us) or how to open one. */
export type NatsConnectionSource = { connection: NatsConnection } | NatsConnectOptions;

/**
 * Opens a connection that reconnects for ever (the owner closes it). A first connection that
 * fails is a HalError naming the servers and the cause: NOT_CONNECTED (nothing there, refused,
 * timed out), or AUTH_FAILED when the server refused the credentials.
 */
export async function openConnection(options: NatsConnectOptions): Promise<NatsConnection> {
  const config: ConnectionOptions = {
    servers: options.servers,
    reconnect: true,
    maxReconnectAttempts: -1,
    reconnectTimeWait: options.reconnectTimeWaitMs ?? 250,
    waitOnFirstConnect: false,
    timeout: 5000,
  };
  if (options.user !== undefined) config.user = options.user;
  if (options.pass !== undefined) config.pass = options.pass;
  if (options.token !== undefined) config.token = options.token;
  if (options.tls !== undefined) config.tls = options.tls;
  if (options.name !== undefined) config.name = options.name;
  try {
    return await connect(config);
  } catch (cause) {
    throw unreachable(options.servers, cause);
  }
}

/** The one error every command gives for a NATS server it could not connect to. */
function unreachable(servers: string | string[], cause: unknown): HalError {
  const where = [servers].flat().join(',');
  const why = errorMessage(cause);
  if (/authori[sz]ation|authentication/i.test(why)) {
    return new HalError('AUTH_FAILED', `NATS at ${where} refused the credentials: ${why}`, {
      cause,
      details: { servers: where },
    });
  }
  return new HalError(
    'NOT_CONNECTED',
    `cannot reach NATS at ${where}: ${why} (is nats-server running there? see --nats or $NATS_URL)`,
    { cause, details: { servers: where } },
  );
}

/** The connection to use and whether we own (and must close) it. */
export async function resolveConnection(
  source: NatsConnectionSource,
): Promise<{ nc: NatsConnection; owned: boolean }> {
  if ('connection' in source) return { nc: source.connection, owned: false };
  return { nc: await openConnection(source), owned: true };
}
