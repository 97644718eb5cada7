// The options of `hal mcp` (those the former hal-mcp command took) and what they ask for.
// Parsing only; commands/mcp.ts runs the server.
import { Option } from 'commander';
import type { Command } from 'commander';
import type { Leash } from '@hal/tools';
import { BUILTIN_MAPS } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import { addLeashOptions, leashFromOptions, numberOption } from '../leash-options.js';
import type { LeashCliOptions } from '../leash-options.js';
import type { RobotTarget } from './robot.js';

/** What the command line asked for. */
export interface McpOptions extends RobotTarget {
  /** Serve streamable HTTP instead of stdio. */
  http: boolean;
  host: string;
  port: number;
  token?: string;
  timeoutMs?: number;
  leash: Leash;
  /** An MCAP file to record the served robot's run into. */
  record?: string;
}

/** The options as commander parses them. */
export interface McpCliOptions extends LeashCliOptions {
  udp?: string;
  serial?: string;
  key?: string;
  map?: BuiltinMapName;
  http: boolean;
  host: string;
  port: number;
  token?: string;
  timeout?: number;
  record?: string;
}

/** Adds the options of `hal mcp` to `command`. */
export function addMcpOptions(command: Command): Command {
  command
    .option('--udp <host[:port]>', 'a robot over WiFi UDP (default port 4210)')
    .option('--serial <path>', 'a robot over a serial port')
    .option('--key <hex>', "the robot's pre-shared key (default $HAL_KEY)")
    .addOption(new Option('--map <name>', "the simulator's map").choices(Object.keys(BUILTIN_MAPS)))
    .option('--http', 'serve streamable HTTP instead of stdio', false)
    .option('--host <address>', 'HTTP address; any but loopback needs --token', '127.0.0.1')
    .option('--port <port>', 'HTTP port', numberOption('--port'), 3333)
    .option('--token <token>', 'bearer token HTTP clients must send (default $HAL_MCP_TOKEN)')
    .option(
      '--timeout <ms>',
      'time one tool call may take (motions get more)',
      numberOption('--timeout'),
    )
    .option(
      '--record <file>',
      "record the robot's run (every tool call's HAL calls, the pose, e-stops) into this MCAP file",
    );
  return addLeashOptions(command);
}

/** What the parsed options ask for; `$HAL_KEY` and `$HAL_MCP_TOKEN` fill in the key and token. */
export function mcpOptions(
  o: McpCliOptions,
  env: Readonly<Record<string, string | undefined>>,
): McpOptions {
  const key = o.key ?? env['HAL_KEY'];
  const token = o.token ?? env['HAL_MCP_TOKEN'];
  return {
    ...(o.udp === undefined ? {} : { udp: o.udp }),
    ...(o.serial === undefined ? {} : { serial: o.serial }),
    ...(key === undefined || key === '' ? {} : { key }),
    ...(o.map === undefined ? {} : { map: o.map }),
    http: o.http,
    host: o.host,
    port: o.port,
    ...(token === undefined || token === '' ? {} : { token }),
    ...(o.timeout === undefined ? {} : { timeoutMs: o.timeout }),
    leash: leashFromOptions(o),
    ...(o.record === undefined ? {} : { record: o.record }),
  };
}
