// A server that could not listen, in the command line's terms: the port or address and the
// option that changes it (`port 8765 is in use (EADDRINUSE); choose another with --ws-port`),
// in place of Node's `listen EADDRINUSE: address already in use 127.0.0.1:8765`.
import { CliError } from './cli-error.js';

/** Where a command listens, and the options that choose it. */
export interface ListenPlace {
  host: string;
  port: number;
  /** The option that sets the port (`--port`, `--ws-port`). */
  portOption: string;
  /** The option that sets the address (`--host`). */
  hostOption: string;
}

/**
 * `error` as a FAILED CliError naming the option to change when it is a listen failure
 * (EADDRINUSE, EACCES, EADDRNOTAVAIL), with its code kept; any other error unchanged.
 */
export function listenError(error: unknown, place: ListenPlace): unknown {
  const code = (error as NodeJS.ErrnoException | undefined)?.code;
  const { host, port, portOption, hostOption } = place;
  switch (code) {
    case 'EADDRINUSE':
      return new CliError(
        'FAILED',
        `port ${port} is in use (EADDRINUSE); choose another with ${portOption}`,
      );
    case 'EACCES':
      return new CliError(
        'FAILED',
        `port ${port} on ${host} needs privileges this process lacks (EACCES); choose one above 1023 with ${portOption}`,
      );
    case 'EADDRNOTAVAIL':
      return new CliError(
        'FAILED',
        `${host} is not an address of this machine (EADDRNOTAVAIL); choose another with ${hostOption}`,
      );
    default:
      return error;
  }
}
