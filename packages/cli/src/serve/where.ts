// Where `hal serve` puts its HAL: on NATS, on WebSocket, or both; parsed from its options.
import { subjectFor } from '@hal/nats';
import type { NatsConnectOptions } from '@hal/nats';
import { CliError } from '../cli-error.js';
import { natsConnectOptions } from '../nats-options.js';
import type { NatsCliOptions } from '../nats-options.js';

export interface ServeCliOptions extends NatsCliOptions {
  device?: string;
  defaultDevice: boolean;
  /** False with --no-mdns: the NATS gateway is not announced by mDNS. */
  mdns?: boolean;
  stateRate?: number;
  wsPort?: number;
  host?: string;
  token?: string;
  /** --allow-origin (repeatable): web pages' origins the WebSocket door trusts without a token. */
  allowOrigin?: string[];
  heartbeatTimeout?: number;
  /** --record: the MCAP file the served robot's run is recorded into. */
  record?: string;
  /** --overwrite: replace the --record file when it exists. */
  overwrite?: boolean;
}

export interface ServePlan {
  nats?: { connect: NatsConnectOptions; defaultDevice: boolean; stateRateHz: number };
  ws?: {
    host: string;
    port: number;
    token?: string;
    allowedOrigins?: string[];
    stateRateHz: number;
    heartbeatTimeoutMs: number;
  };
}

/** NATS state streams default to 20 Hz, WebSocket state to 10 Hz (each package's default). */
const NATS_STATE_HZ = 20;
const WS_STATE_HZ = 10;
const WS_HEARTBEAT_MS = 2000;

/** The plan, or a USAGE error when it names neither NATS nor WebSocket. */
export function servePlan(
  o: ServeCliOptions,
  env: Readonly<Record<string, string | undefined>>,
): ServePlan {
  const natsNamed = o.nats !== undefined;
  if (!natsNamed) {
    const natsOnly: [unknown, string][] = [
      [o.defaultDevice ? undefined : false, '--no-default-device'],
      [o.natsUser, '--nats-user'],
      [o.natsPass, '--nats-pass'],
      [o.natsToken, '--nats-token'],
      [o.natsCa, '--nats-ca'],
      [o.natsCert, '--nats-cert'],
      [o.natsKey, '--nats-key'],
    ];
    for (const [value, name] of natsOnly) {
      if (value !== undefined) throw new CliError('USAGE', `"${name}" needs --nats <servers>`);
    }
  }
  const wsNamed = o.wsPort !== undefined;
  if (!natsNamed && !wsNamed) {
    throw new CliError(
      'USAGE',
      'say where to serve: --nats <servers> for NATS, --ws-port <port> for WebSocket, or both',
    );
  }
  if (!wsNamed) {
    // $HAL_SERVE_TOKEN may be set for other commands; only an explicit --token is refused
    for (const [value, name] of [
      [o.host, '--host'],
      [o.token, '--token'],
      [o.allowOrigin, '--allow-origin'],
      [o.heartbeatTimeout, '--heartbeat-timeout'],
    ] as const) {
      if (value !== undefined) throw new CliError('USAGE', `"${name}" needs --ws-port`);
    }
  }
  if (natsNamed && o.stateRate !== undefined && o.stateRate !== 0) {
    if (o.stateRate < 10 || o.stateRate > 100) {
      throw new CliError('USAGE', '"--state-rate" on NATS is 10..100 Hz (0: no state streams)');
    }
  }
  const plan: ServePlan = {};
  if (natsNamed) {
    plan.nats = {
      connect: natsConnectOptions(o, env, 'hal-serve'),
      defaultDevice: o.defaultDevice,
      stateRateHz: o.stateRate ?? NATS_STATE_HZ,
    };
  }
  if (wsNamed) {
    const token = o.token ?? env['HAL_SERVE_TOKEN'];
    plan.ws = {
      host: o.host ?? '127.0.0.1',
      port: o.wsPort!,
      ...(token === undefined ? {} : { token }),
      ...(o.allowOrigin === undefined ? {} : { allowedOrigins: o.allowOrigin }),
      stateRateHz: o.stateRate === undefined || o.stateRate === 0 ? WS_STATE_HZ : o.stateRate,
      heartbeatTimeoutMs: o.heartbeatTimeout ?? WS_HEARTBEAT_MS,
    };
  }
  return plan;
}

/** The subjects a device is served on, for the "serving" message. */
export function servedSubjects(deviceId: string, defaultDevice: boolean): string[] {
  const prefix = subjectFor('call', deviceId).replace(/\.hal\.call\.req$/, '.>');
  return defaultDevice ? [prefix, 'hal.v1.> (the default device)'] : [prefix];
}
