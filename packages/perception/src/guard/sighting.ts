/** What saw the way ahead. */
export type GuardSource = 'camera' | 'range';

/** One look ahead: how far the corridor the body sweeps driving straight is free. */
export interface Sighting {
  /** Free distance ahead of the body's front, metres (the sense's range when nothing is seen). */
  aheadM: number;
  /** Whether something was seen in the corridor. */
  blocked: boolean;
  /**
   * Whether what was seen reaches the edge of the sense's view (below the image, or nearer than
   * the sensor's shortest reading): it is at `aheadM` or nearer.
   */
  atEdge: boolean;
  source: GuardSource;
  /** When the look ended, ms since the epoch. */
  at: number;
}

/** A way of looking ahead. `look` rejects with a HalError when it cannot see. */
export interface Sight {
  readonly source: GuardSource;
  look(): Promise<Sighting>;
}
