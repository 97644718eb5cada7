/** Log levels, least to most severe. */
export type LogLevel = 'debug' | 'info' | 'warn' | 'error';

/**
 * Where the package writes what it does. Inject one (pino, a test recorder, a telemetry sink);
 * the default drops everything, because a library never writes to the console. `namespace` says
 * which part wrote the entry (`hal:physical:udp`, `hal:physical:session`, ...).
 */
export interface Logger {
  log(level: LogLevel, namespace: string, message: string, fields?: Record<string, unknown>): void;
}

/** A logger that drops everything. */
export const silentLogger: Logger = Object.freeze({ log: () => undefined });

/** A logger bound to one namespace. */
export interface ScopedLogger {
  debug(message: string, fields?: Record<string, unknown>): void;
  info(message: string, fields?: Record<string, unknown>): void;
  warn(message: string, fields?: Record<string, unknown>): void;
  error(message: string, fields?: Record<string, unknown>): void;
}

/** Binds a logger to a namespace. A logger that throws is ignored: logging never breaks a call. */
export function scoped(logger: Logger, namespace: string): ScopedLogger {
  const write =
    (level: LogLevel) =>
    (message: string, fields?: Record<string, unknown>): void => {
      try {
        logger.log(level, namespace, message, fields);
      } catch {
        // a broken logger must not break the robot link
      }
    };
  return { debug: write('debug'), info: write('info'), warn: write('warn'), error: write('error') };
}
