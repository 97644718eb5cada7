import type { HardwareAbstractionLayer, ScopedLogger } from '@hal/types';
import type { GuardSettings } from './guard-settings.js';
import type { GuardRecord } from './guard-status.js';
import type { Sight } from './sighting.js';

/** What the guarded locomotion works with. */
export interface GuardContext {
  hal: HardwareAbstractionLayer;
  settings: GuardSettings;
  record: GuardRecord;
  log: ScopedLogger;
  /** How the guard sees ahead; undefined when it cannot (it has said so). */
  sight(): Promise<Sight | undefined>;
}
