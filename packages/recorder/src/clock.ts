/** Nanoseconds since the epoch, never going backwards (the wall clock may step; this does not). */
export function monotonicEpochClock(): () => bigint {
  const origin = BigInt(Math.round(performance.timeOrigin * 1e6));
  let last = 0n;
  return () => {
    const now = origin + BigInt(Math.round(performance.now() * 1e6));
    last = now > last ? now : last + 1n;
    return last;
  };
}
