// The options of `hal mcp`: the robot (the target options every command takes, the embedded
// simulator when none is named, maybe in a --world), how to serve (stdio, or HTTP at --host/--port
// with --http-token), the tools offered (--tools), who approves motions (--approve), the leash,
// and --record. Parsing only;
// commands/mcp.ts runs the server.
import { Option } from 'commander';
import type { Command } from 'commander';
import { DEFAULT_APPROVAL_TIMEOUT_MS, parseApprovalPolicy } from '@hal/mcp';
import type { ApprovalPolicy } from '@hal/mcp';
import { isLoopback } from '@hal/runtime';
import { isToolProfile, TOOL_PROFILES } from '@hal/skills';
import type { ToolProfile } from '@hal/skills';
import type { Leash } from '@hal/tools';
import { addLeashOptions, leashFromOptions } from '../leash-options.js';
import type { LeashCliOptions } from '../leash-options.js';
import { addOverwriteOption } from '../output-place.js';
import { addTargetOptions, namesTarget, resolveTarget } from '../target.js';
import type { Target, TargetCliOptions } from '../target.js';
import { integerArg, portArg, readQuantity, usageError } from '../values.js';

/** The default HTTP port of `hal mcp --http`. */
export const DEFAULT_MCP_HTTP_PORT = 3333;

/** What the command line asked for. */
export interface McpOptions {
  /** The robot served. */
  target: Target;
  /** The world file the embedded simulator starts in (eval task format). */
  world?: string;
  /** The tools offered: the HAL's calls (`primitives`), the skills, or `all`. */
  profile: ToolProfile;
  /** Give up connecting to the robot after this long, ms. */
  connectTimeoutMs?: number;
  /** Serve streamable HTTP instead of stdio. */
  http: boolean;
  host: string;
  port: number;
  /** The bearer token HTTP clients must send. */
  token?: string;
  timeoutMs?: number;
  leash: Leash;
  /** Who approves motions: the client's user before every one, or one over a distance, or no one. */
  approve: ApprovalPolicy;
  /** How long the user has to answer, ms. */
  approvalTimeoutMs: number;
  /** An MCAP file to record the served robot's run into. */
  record?: string;
  /** Replace the --record file when it exists. */
  overwrite: boolean;
}

/** The options as commander parses them. */
export interface McpCliOptions extends TargetCliOptions, LeashCliOptions {
  tools: string;
  world?: string;
  http: boolean;
  host: string;
  port: number;
  httpToken?: string;
  timeout?: number;
  approve: ApprovalPolicy;
  approvalTimeout: number;
  record?: string;
  overwrite?: boolean;
}

/** Adds the options of `hal mcp` to `command`. */
export function addMcpOptions(command: Command): Command {
  command
    .addOption(
      new Option(
        '--tools <profile>',
        'the tools offered: primitives (the HAL calls), skills (look, find, go_to, ...: few tools, for small models) or all',
      ).default('primitives'),
    )
    .addOption(
      new Option(
        '--world <file>',
        'with --sim: the world the simulator starts in, in the eval task format ({ map, start, objects })',
      ),
    )
    .option('--http', 'serve streamable HTTP (a session per client) instead of stdio', false)
    .option('--host <address>', 'HTTP address; any but loopback needs --http-token', '127.0.0.1')
    .addOption(
      new Option('--port <port>', 'HTTP port (0: any free one)')
        .argParser(portArg('--port', { anyFree: true }))
        .default(DEFAULT_MCP_HTTP_PORT),
    )
    .option(
      '--http-token <token>',
      'bearer token HTTP clients must send, 16+ characters (default $HAL_MCP_TOKEN)',
    )
    .addOption(
      new Option('--timeout <ms>', 'time one tool call may take (motions get more)').argParser(
        integerArg('--timeout', 100, 600_000),
      ),
    )
    .addOption(
      new Option(
        '--approve <policy>',
        "who approves motions: motion (the MCP client's user, before every motion, by elicitation), over:DISTANCE (only one longer than that: over:30cm) or none",
      )
        .argParser(approvalArg)
        .default('none' as ApprovalPolicy, 'none'),
    )
    .addOption(
      new Option(
        '--approval-timeout <ms>',
        'how long the user has to answer an approval; no answer is a no',
      )
        .argParser(integerArg('--approval-timeout', 100, 3_600_000))
        .default(DEFAULT_APPROVAL_TIMEOUT_MS),
    )
    .option(
      '--record <file>',
      "record the robot's run (every tool call's HAL calls, the pose, e-stops) into this MCAP file",
    );
  addOverwriteOption(command, 'the --record file');
  addLeashOptions(command);
  return addTargetOptions(command);
}

/** `--approve`: motion, none or over:DISTANCE, or USAGE. */
export function approvalArg(text: string): ApprovalPolicy {
  try {
    return parseApprovalPolicy(text, (d) => readQuantity(d, 'distance'));
  } catch {
    throw usageError(
      `"--approve" must be motion, none or over:DISTANCE (metres, or with a unit: over:30cm), got "${text}"`,
    );
  }
}

/** `--tools`: a profile's name, or USAGE listing the three. */
export function profileArg(text: string): ToolProfile {
  if (isToolProfile(text)) return text;
  throw usageError(`"--tools" must be one of ${TOOL_PROFILES.join(', ')}, got "${text}"`);
}

/**
 * What the parsed options ask for: the robot they name (the embedded simulator when none),
 * `$HAL_MCP_TOKEN` for the HTTP token. USAGE for a robot named twice, a tool profile that is none,
 * a --world beside --map or another robot than the simulator, or HTTP beyond loopback without a
 * token of 16 characters or more.
 */
export function mcpOptions(
  o: McpCliOptions,
  env: Readonly<Record<string, string | undefined>>,
): McpOptions {
  const target = resolveTarget(namesTarget(o) ? o : { ...o, sim: true }, env);
  const profile = profileArg(o.tools);
  if (o.world !== undefined) {
    if (target.kind !== 'sim') throw usageError('"--world" needs the simulator (--sim)');
    if (o.map !== undefined)
      throw usageError('"--world" and "--map" both name the world: give one');
  }
  const token = o.httpToken ?? env['HAL_MCP_TOKEN'];
  const hasToken = token !== undefined && token !== '';
  if (o.http && !isLoopback(o.host) && (!hasToken || token.length < 16)) {
    throw usageError(
      `"--host" ${o.host} is reachable from other machines: give --http-token (16+ characters, or $HAL_MCP_TOKEN)`,
    );
  }
  return {
    target,
    ...(o.world === undefined ? {} : { world: o.world }),
    profile,
    ...(o.connectTimeout === undefined ? {} : { connectTimeoutMs: o.connectTimeout }),
    http: o.http,
    host: o.host,
    port: o.port,
    ...(hasToken ? { token } : {}),
    ...(o.timeout === undefined ? {} : { timeoutMs: o.timeout }),
    leash: leashFromOptions(o),
    approve: o.approve,
    approvalTimeoutMs: o.approvalTimeout,
    ...(o.record === undefined ? {} : { record: o.record }),
    overwrite: o.overwrite === true,
  };
}
