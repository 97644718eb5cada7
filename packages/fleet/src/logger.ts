/** Where the fleet writes what it does (never the console). Default: drops everything. */
export interface FleetLogger {
  debug(message: string, fields?: Record<string, unknown>): void;
  info(message: string, fields?: Record<string, unknown>): void;
  warn(message: string, fields?: Record<string, unknown>): void;
  error(message: string, fields?: Record<string, unknown>): void;
}

const drop = (): void => undefined;

/** A logger that says nothing. */
export const silentFleetLogger: FleetLogger = Object.freeze({
  debug: drop,
  info: drop,
  warn: drop,
  error: drop,
});
