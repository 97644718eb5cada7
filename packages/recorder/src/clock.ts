const ORIGIN_NS = BigInt(Math.round(performance.timeOrigin * 1e6));

/** Nanoseconds since the epoch at `ms`, a reading of `performance.now()`. */
export function epochNsAt(ms: number): bigint {
  return ORIGIN_NS + BigInt(Math.round(ms * 1e6));
}

/** Nanoseconds since the epoch, never going backwards (the wall clock may step; this does not). */
export function monotonicEpochClock(): () => bigint {
  let last = 0n;
  return () => {
    const now = epochNsAt(performance.now());
    last = now > last ? now : last + 1n;
    return last;
  };
}
