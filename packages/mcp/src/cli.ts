import { StdioServerTransport } from '@modelcontextprotocol/sdk/server/stdio.js';
import { createToolExecutor, halTools } from '@hal/tools';
import type { Leash } from '@hal/tools';
import { BUILTIN_MAPS } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import { Command, Option } from 'commander';
import { addLeashOptions, leashFromOptions, numberOption } from './leash-options.js';
import type { LeashCliOptions } from './leash-options.js';
import { serveHttp } from './http.js';
import { createRobot } from './robot.js';
import type { RobotTarget } from './robot.js';
import { createRobotMcpServer } from './server.js';

/** What the command line asked for. */
export interface CliOptions extends RobotTarget {
  /** Serve streamable HTTP instead of stdio. */
  http: boolean;
  host: string;
  port: number;
  token?: string;
  timeoutMs?: number;
  leash: Leash;
}

function command(): Command {
  const program = new Command('hal-mcp')
    .description(
      'MCP server for the robot: the HAL tools, its state, capabilities and map as resources. ' +
        'Drives the embedded simulator unless --udp or --serial names a robot.',
    )
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
    .exitOverride()
    .configureOutput({
      writeOut: (s) => process.stderr.write(s),
      writeErr: (s) => process.stderr.write(s),
    });
  return addLeashOptions(program);
}

/**
 * Parses the command line (`argv` without node and the script). Throws on bad options. A leading
 * `--` is dropped: `pnpm --filter @hal/mcp start -- --map obstacles` passes it on, and hal-mcp
 * takes no positional arguments it could separate.
 */
export function parseCli(
  argv: readonly string[],
  env: NodeJS.ProcessEnv = process.env,
): CliOptions {
  const args = argv[0] === '--' ? argv.slice(1) : [...argv];
  const o = command().parse(args, { from: 'user' }).opts<Record<string, unknown>>();
  const key = (o['key'] as string | undefined) ?? env['HAL_KEY'];
  const token = (o['token'] as string | undefined) ?? env['HAL_MCP_TOKEN'];
  const leash = leashFromOptions(o as LeashCliOptions);
  return {
    ...(o['udp'] === undefined ? {} : { udp: o['udp'] as string }),
    ...(o['serial'] === undefined ? {} : { serial: o['serial'] as string }),
    ...(key === undefined || key === '' ? {} : { key }),
    ...(o['map'] === undefined ? {} : { map: o['map'] as BuiltinMapName }),
    http: o['http'] === true,
    host: o['host'] as string,
    port: o['port'] as number,
    ...(token === undefined || token === '' ? {} : { token }),
    ...(o['timeout'] === undefined ? {} : { timeoutMs: o['timeout'] as number }),
    leash,
  };
}

/**
 * Runs the server until stdin closes (stdio) or a signal arrives; the robot is cleaned up (its
 * motors stopped) on the way out. Messages go to stderr: stdout carries the protocol.
 */
export async function runCli(argv: readonly string[]): Promise<void> {
  const options = parseCli(argv);
  const { hal, world } = createRobot(options);
  await hal.initialize();
  const executor = createToolExecutor(hal, {
    tools: halTools(hal),
    leash: options.leash,
    ...(options.timeoutMs === undefined ? {} : { timeoutMs: options.timeoutMs }),
  });
  const create = () => createRobotMcpServer(hal, executor, world);
  let stopping = false;
  let closeTransport: () => Promise<void> = async () => undefined;
  const shutdown = async () => {
    if (stopping) return;
    stopping = true;
    await closeTransport().catch(() => undefined);
    await hal.cleanup().catch(() => undefined);
    process.exit(0);
  };
  process.once('SIGINT', () => void shutdown());
  process.once('SIGTERM', () => void shutdown());
  if (options.http) {
    const endpoint = await serveHttp(create, {
      host: options.host,
      port: options.port,
      ...(options.token === undefined ? {} : { token: options.token }),
    });
    closeTransport = endpoint.close;
    process.stderr.write(`hal-mcp: ${hal.mode} robot, MCP over HTTP at ${endpoint.url}\n`);
  } else {
    const server = create();
    await server.connect(new StdioServerTransport());
    closeTransport = () => server.close();
    process.stdin.once('end', () => void shutdown());
    process.stderr.write(`hal-mcp: ${hal.mode} robot, MCP over stdio\n`);
  }
}
