import type { FleetLogger } from '@hal/fleet';
import type { ResultsLog } from '../results-log.js';

/** The fleet's warnings and errors, as notes in the results list (debug and info are dropped). */
export function fleetLogger(log: ResultsLog): FleetLogger {
  const note = (message: string, fields?: Record<string, unknown>) =>
    log.note(`fleet: ${message}${fields === undefined ? '' : ` ${JSON.stringify(fields)}`}`);
  return {
    debug: () => undefined,
    info: () => undefined,
    warn: note,
    error: note,
  };
}
