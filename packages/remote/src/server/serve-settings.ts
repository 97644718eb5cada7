import { trustedOrigin } from '@hal/runtime';
import { HalError } from '@hal/types';
import { checkBinding } from './auth.js';
import { SERVE_DEFAULTS } from './options.js';
import type { ServeHalOptions } from './options.js';

/** The settings of one server, defaults filled in and checked. */
export interface ServeSettings {
  host: string;
  port: number;
  token: string | undefined;
  allowedOrigins: ReadonlySet<string>;
  heartbeatTimeoutMs: number;
  stateRateHz: number;
  maxMessageBytes: number;
}

/** Reads `options` into {@link ServeSettings}; throws a HalError when they are unsafe. */
export function serveSettings(options: ServeHalOptions): ServeSettings {
  const host = options.host ?? SERVE_DEFAULTS.host;
  // an empty token is none, as checkBinding reads it
  const token = options.token === '' ? undefined : options.token;
  checkBinding(host, token);
  const allowedOrigins = new Set((options.allowedOrigins ?? []).map((o) => trustedOrigin(o)));
  const heartbeatTimeoutMs = options.heartbeatTimeoutMs ?? SERVE_DEFAULTS.heartbeatTimeoutMs;
  if (!(heartbeatTimeoutMs >= 100 && heartbeatTimeoutMs <= 10_000)) {
    throw new HalError('RANGE_EXCEEDED', '"heartbeatTimeoutMs" must be 100..10000 ms', {
      details: { parameter: 'heartbeatTimeoutMs', received: heartbeatTimeoutMs },
    });
  }
  return {
    host,
    port: options.port ?? SERVE_DEFAULTS.port,
    token,
    allowedOrigins,
    heartbeatTimeoutMs,
    stateRateHz: options.stateRateHz ?? SERVE_DEFAULTS.stateRateHz,
    maxMessageBytes: options.maxMessageBytes ?? SERVE_DEFAULTS.maxMessageBytes,
  };
}
