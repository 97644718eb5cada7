// The HAL's warnings and errors, written to stderr: as text for people, or as one JSON line each
// with --json (so stderr stays parseable). Debug and info are dropped.
import type { Logger } from '@hal/types';
import type { CliIO } from './io.js';

export function cliLogger(io: CliIO, json: boolean): Logger {
  return {
    log: (level, namespace, message) => {
      if (level !== 'warn' && level !== 'error') return;
      io.err(
        json
          ? `${JSON.stringify({ log: { level, namespace, message } })}\n`
          : `${level} ${namespace} ${message}\n`,
      );
    },
  };
}
