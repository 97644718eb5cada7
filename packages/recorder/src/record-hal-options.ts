import type { Logger } from '@hal/types';

/** What `recordHal` records besides the calls. */
export interface RecordHalOptions {
  /** Pose sample period while the HAL is ready, ms; 0 samples only after motions. Default 100. */
  posePeriodMs?: number;
  /** The robot's id for the metadata, when it is not the HAL's own `getDeviceInfo().id`. */
  deviceId?: string;
  /** The map the robot runs in (any JSON), for the metadata record `hal.robot`. */
  map?: unknown;
  /** The project's version, for the metadata (default this package's). */
  version?: string;
  /** Where the recorder's own warnings go. */
  logger?: Logger;
  /**
   * A physical robot's link statistics (`/hal/link`) are written every `linkPeriodMs` while the
   * HAL is ready, and once more as it is cleaned up. Default 1000; 0 writes only that last one.
   */
  linkPeriodMs?: number;
  /**
   * The robot's namespace in a recording of several robots (a fleet): its topics go under
   * `/<namespace>` (`/sim-1/hal/calls`), its frames are `<namespace>/base_link` and
   * `<namespace>/camera` in the shared `world`, its metadata record is `hal.robot/<namespace>`.
   * 1-64 letters, digits, `-` or `_` (INVALID_PARAMETER otherwise). Default: none.
   */
  namespace?: string;
  /** Stops the pose sampling when aborted (it also stops on `cleanup()` through the proxy). */
  signal?: AbortSignal;
}
