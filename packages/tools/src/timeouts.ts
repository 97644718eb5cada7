/** Default time a tool call may take before the executor answers TIMEOUT, ms. */
export const DEFAULT_TOOL_TIMEOUT_MS = 10_000;

/**
 * The timeout of one call: `base` for everything but motion; a motion gets `base` plus twice its
 * profile's duration (a loaded machine, retries, a robot that starts late), so a long legitimate
 * move is never cut by the executor's timer.
 */
export function callTimeoutMs(base: number, profileMs: number | undefined): number {
  if (profileMs === undefined || !Number.isFinite(profileMs)) return base;
  return Math.ceil(base + 2 * profileMs);
}
