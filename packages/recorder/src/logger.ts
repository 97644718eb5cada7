/** A logger the recorder reports through (it never uses the console); the HALs' loggers fit. */
export interface RecorderLogger {
  warn(message: string, fields?: Record<string, unknown>): void;
  info?(message: string, fields?: Record<string, unknown>): void;
}

/** Calls a logger and swallows what it throws: logging never breaks a call. */
export function safeWarn(
  logger: RecorderLogger | undefined,
  message: string,
  fields?: Record<string, unknown>,
): void {
  try {
    logger?.warn(message, fields);
  } catch {
    // a failing logger must not reach the robot
  }
}
