/** Log levels, least to most severe. */
export type RemoteLogLevel = 'debug' | 'info' | 'warn' | 'error';

/**
 * Where the remote HAL writes what it does (namespaces `hal:remote:server`, `hal:remote:client`).
 * The same shape as `@hal/physical`'s `Logger`, so one logger serves both. Default: drop everything.
 */
export interface RemoteLogger {
  log(
    level: RemoteLogLevel,
    namespace: string,
    message: string,
    fields?: Record<string, unknown>,
  ): void;
}

/** A logger that drops everything. */
export const silentRemoteLogger: RemoteLogger = Object.freeze({ log: () => undefined });

/** Writes through `logger`; a logger that throws is ignored, so logging never breaks a call. */
export function writeLog(
  logger: RemoteLogger,
  level: RemoteLogLevel,
  namespace: string,
  message: string,
  fields?: Record<string, unknown>,
): void {
  try {
    logger.log(level, namespace, message, fields);
  } catch {
    // logging must never break the link
  }
}
