/** Log levels, least to most severe. */
export type LogLevel = 'debug' | 'info' | 'warn' | 'error';

/**
 * Where a package writes what it does: every package takes one of these (option `logger`) and
 * none writes to the console. Inject one (pino, a test recorder, a telemetry sink); the default
 * is {@link silentLogger}. `namespace` says which part wrote the entry (`hal:physical:udp`,
 * `hal:nats:gateway`, `hal:agent`, ...), so one logger serves every package.
 */
export interface Logger {
  log(level: LogLevel, namespace: string, message: string, fields?: Record<string, unknown>): void;
}

/** A logger that drops everything: the default of every package. */
export const silentLogger: Logger = Object.freeze({ log: () => undefined });

/** A logger bound to one namespace, one method per level: what a package writes through. */
export type ScopedLogger = Readonly<
  Record<LogLevel, (message: string, fields?: Record<string, unknown>) => void>
>;

/** Binds a logger to a namespace. A logger that throws is ignored: logging never breaks a call. */
export function scoped(logger: Logger, namespace: string): ScopedLogger {
  const write =
    (level: LogLevel) =>
    (message: string, fields?: Record<string, unknown>): void => {
      try {
        logger.log(level, namespace, message, fields);
      } catch {
        // a broken logger must not break the call that logged
      }
    };
  return Object.freeze({
    debug: write('debug'),
    info: write('info'),
    warn: write('warn'),
    error: write('error'),
  });
}
