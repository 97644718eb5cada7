import type { Logger } from '@hal/types';
import type { ResultsLog } from '../results-log.js';

/** The fleet's warnings and errors, as notes in the results list (debug and info are dropped). */
export function fleetLogger(log: ResultsLog): Logger {
  return {
    log: (level, _namespace, message, fields) => {
      if (level !== 'warn' && level !== 'error') return;
      log.note(`fleet: ${message}${fields === undefined ? '' : ` ${JSON.stringify(fields)}`}`);
    },
  };
}
