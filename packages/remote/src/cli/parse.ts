// The command line of hal-serve, parsed with commander. Parsing is separate from running so it can
// be tested without opening anything.
import { Command, Option } from 'commander';
import {
  hexKeyArg as hexKey,
  hostPortArg,
  integerArg as integer,
  positiveArg as positive,
} from './values.js';

/** Which HAL to serve. */
export type HalChoice =
  | { kind: 'sim' }
  | { kind: 'udp'; host: string; port: number; key?: string }
  | { kind: 'serial'; path: string; baudRate?: number; key?: string };

export interface ServeCommand {
  hal: HalChoice;
  host: string;
  port: number;
  token?: string;
  deviceId: string;
  stateRateHz: number;
  heartbeatTimeoutMs: number;
  /** Time scale of an emulated robot's clock (PhysicalHAL `timeScale`). */
  timeScale: number;
}

/** Builds the program. `exitOverride` turns its exits into CommanderErrors (for tests). */
export function serveProgram(): Command {
  return new Command('hal-serve')
    .description('Serve one robot HAL over WebSocket (see docs/remote.md)')
    .addOption(
      new Option('--sim', 'serve an embedded simulator (the default)').conflicts(['udp', 'serial']),
    )
    .addOption(
      new Option(
        '--udp <host[:port]>',
        'serve the robot at this UDP address (port 4210 by default)',
      )
        .argParser(hostPortArg('--udp'))
        .conflicts(['serial']),
    )
    .option('--serial <path>', 'serve the robot on this serial port')
    .option('--baud <rate>', 'serial baud rate', integer('--baud', 1200, 4_000_000))
    .option('--key <hex>', "the robot's pre-shared key, hex", hexKey)
    .option('--host <address>', 'address to listen on (not loopback: --token needed)', '127.0.0.1')
    .option(
      '--port <port>',
      'TCP port to listen on (0: any free one)',
      integer('--port', 0, 65_535),
      8765,
    )
    .addOption(
      new Option('--token <secret>', 'token clients must present (at least 16 characters)').env(
        'HAL_SERVE_TOKEN',
      ),
    )
    .option('--device-id <id>', 'device id of the served robot', 'cube-1')
    .option('--state-rate <hz>', 'state messages per second', positive('--state-rate'), 10)
    .option(
      '--heartbeat-timeout <ms>',
      'drop a silent client (and stop its motion) after this long',
      integer('--heartbeat-timeout', 100, 10_000),
      2000,
    )
    .option(
      '--time-scale <factor>',
      "an emulated robot's clock speed-up",
      positive('--time-scale'),
      1,
    )
    .showHelpAfterError();
}

interface RawOptions {
  sim?: boolean;
  udp?: { host: string; port: number };
  serial?: string;
  baud?: number;
  key?: string;
  host: string;
  port: number;
  token?: string;
  deviceId: string;
  stateRate: number;
  heartbeatTimeout: number;
  timeScale: number;
}

/**
 * Parses `argv` (without node and the script). On bad input commander prints the error and exits,
 * or throws a CommanderError when the program has `exitOverride()` (tests).
 */
export function parseServeCommand(argv: readonly string[], program = serveProgram()): ServeCommand {
  program.parse([...argv], { from: 'user' });
  const o = program.opts<RawOptions>();
  if (o.key !== undefined && o.udp === undefined && o.serial === undefined) {
    program.error('error: "--key" needs --udp or --serial');
  }
  let hal: HalChoice = { kind: 'sim' };
  const key = o.key === undefined ? {} : { key: o.key };
  if (o.udp !== undefined) hal = { kind: 'udp', ...o.udp, ...key };
  if (o.serial !== undefined) {
    hal = {
      kind: 'serial',
      path: o.serial,
      ...key,
      ...(o.baud === undefined ? {} : { baudRate: o.baud }),
    };
  }
  const command: ServeCommand = {
    hal,
    host: o.host,
    port: o.port,
    deviceId: o.deviceId,
    stateRateHz: o.stateRate,
    heartbeatTimeoutMs: o.heartbeatTimeout,
    timeScale: o.timeScale,
  };
  if (o.token !== undefined) command.token = o.token;
  return command;
}
