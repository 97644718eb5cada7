/** Where the package writes what it does (never the console). Default: drops everything. */
export interface NatsLogger {
  debug(message: string, fields?: Record<string, unknown>): void;
  info(message: string, fields?: Record<string, unknown>): void;
  warn(message: string, fields?: Record<string, unknown>): void;
  error(message: string, fields?: Record<string, unknown>): void;
}

const drop = (): void => undefined;
export const silentNatsLogger: NatsLogger = Object.freeze({
  debug: drop,
  info: drop,
  warn: drop,
  error: drop,
});
