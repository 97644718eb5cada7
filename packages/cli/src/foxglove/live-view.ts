// `--foxglove [PORT]`: a live view of the command's robot for Foxglove or Lichtblick, beside
// whatever else the command does (`hal serve`, `hal agent`, `hal mcp`). The options, their
// parsing, and starting, announcing and stopping the view, in one place, so each command wires it
// in three lines:
//
//   addFoxgloveOptions(command);                                    // at registration
//   const live = await startLiveView(hal, options, ctx, { deviceId, leash }); // once the HAL is open
//   ... use live.hal (calls through it show in the view) ...; await live.close();
import { Option } from 'commander';
import type { Command } from 'commander';
import { FOXGLOVE_DEFAULTS, serveFoxglove } from '@hal/foxglove';
import type { FoxgloveLiveServer, FoxgloveServeOptions } from '@hal/foxglove';
import { checkBinding } from '@hal/remote/server';
import type { RecordablePerception } from '@hal/recorder';
import type { Leash } from '@hal/tools';
import type { HardwareAbstractionLayer } from '@hal/types';
import { CliError } from '../cli-error.js';
import { listenError } from '../listen-error.js';
import { cliLogger } from '../logger.js';
import { allowOriginArg } from '../serve/allow-origin.js';
import { integerArg } from '../values.js';
import type { CommandContext } from '../commands/context.js';

/** The options as commander parses them. */
export interface FoxgloveCliOptions {
  /** --foxglove [PORT]: the port (8765 when the flag has none; 0: any free one). */
  foxglove?: number;
  foxgloveHost?: string;
  foxgloveToken?: string;
  foxgloveAllowOrigin?: string[];
  foxgloveCameraRate?: number;
}

/** Adds --foxglove [PORT] and its --foxglove-* options to `command`. */
export function addFoxgloveOptions(command: Command): Command {
  return command
    .addOption(
      new Option(
        '--foxglove [port]',
        `serve a live view for Foxglove or Lichtblick on this TCP port (default ${FOXGLOVE_DEFAULTS.port}; 0: any free one)`,
      )
        .preset(String(FOXGLOVE_DEFAULTS.port))
        .argParser(integerArg('--foxglove', 0, 65_535)),
    )
    .addOption(
      new Option(
        '--foxglove-host <address>',
        'address the live view listens on (default 127.0.0.1; not loopback: a token needed)',
      ),
    )
    .addOption(
      new Option(
        '--foxglove-token <secret>',
        'token viewers must present as ws://HOST:PORT/?token=..., 16+ characters (default $HAL_FOXGLOVE_TOKEN)',
      ),
    )
    .addOption(
      new Option(
        '--foxglove-allow-origin <origin>',
        'trust a web viewer from this origin without a token, e.g. https://app.foxglove.dev (repeatable)',
      ).argParser(allowOriginArg),
    )
    .addOption(
      new Option(
        '--foxglove-camera-rate <hz>',
        `camera frames per second to viewers (0: no camera; default ${FOXGLOVE_DEFAULTS.cameraRateHz})`,
      ).argParser(integerArg('--foxglove-camera-rate', 0, 30)),
    );
}

/**
 * The live view the options ask for, or undefined without --foxglove (USAGE for a --foxglove-*
 * option without it). Checks the binding at once (a non-loopback address needs a token), so a
 * command refuses before it opens the robot.
 */
export function foxglovePlan(
  options: FoxgloveCliOptions,
  env: Readonly<Record<string, string | undefined>>,
): FoxgloveServeOptions | undefined {
  if (options.foxglove === undefined) {
    for (const [value, name] of [
      [options.foxgloveHost, '--foxglove-host'],
      [options.foxgloveToken, '--foxglove-token'],
      [options.foxgloveAllowOrigin, '--foxglove-allow-origin'],
      [options.foxgloveCameraRate, '--foxglove-camera-rate'],
    ] as const) {
      if (value !== undefined) throw new CliError('USAGE', `"${name}" needs --foxglove`);
    }
    return undefined;
  }
  const token = options.foxgloveToken ?? env['HAL_FOXGLOVE_TOKEN'];
  const plan: FoxgloveServeOptions = {
    host: options.foxgloveHost ?? FOXGLOVE_DEFAULTS.host,
    port: options.foxglove,
    ...(token === undefined || token === '' ? {} : { token }),
    ...(options.foxgloveAllowOrigin === undefined
      ? {}
      : { allowedOrigins: options.foxgloveAllowOrigin }),
    ...(options.foxgloveCameraRate === undefined
      ? {}
      : { cameraRateHz: options.foxgloveCameraRate }),
  };
  try {
    checkBinding(plan.host!, plan.token);
  } catch (error) {
    throw new CliError(
      'USAGE',
      `${(error as Error).message.replace('hal serve --token', '--foxglove-token')}`,
    );
  }
  return plan;
}

/** A live view started by a command. */
export interface LiveView {
  /** The robot's HAL with the view's tap: use it for everything the command does. */
  readonly hal: HardwareAbstractionLayer;
  /** Where viewers connect, e.g. ws://127.0.0.1:8765. */
  readonly url: string | undefined;
  /** Stops the view, and says what slow viewers lost (nothing when none was started). */
  close(): Promise<void>;
}

/**
 * Starts the live view `plan` asks for on `hal` and says where (`{event: "foxglove", url}`
 * with --json); with no plan, `hal` itself and nothing to stop.
 */
export async function startLiveView(
  hal: HardwareAbstractionLayer,
  plan: FoxgloveServeOptions | undefined,
  { io, global }: CommandContext,
  extra: { deviceId?: string; leash?: Leash; perception?: RecordablePerception } = {},
): Promise<LiveView> {
  if (plan === undefined) return { hal, url: undefined, close: async () => undefined };
  const logger = cliLogger(io, global().json);
  let server: FoxgloveLiveServer;
  try {
    server = await serveFoxglove(hal, {
      ...plan,
      logger,
      ...(extra.deviceId === undefined ? {} : { deviceId: extra.deviceId }),
      ...(extra.leash === undefined ? {} : { leash: extra.leash }),
      ...(extra.perception === undefined ? {} : { perception: extra.perception }),
    });
  } catch (error) {
    throw listenError(error, {
      host: plan.host ?? FOXGLOVE_DEFAULTS.host,
      port: plan.port ?? FOXGLOVE_DEFAULTS.port,
      portOption: '--foxglove',
      hostOption: '--foxglove-host',
    });
  }
  let closed = false;
  const open = plan.token === undefined ? server.url : `${server.url}/?token=<token>`;
  // progress on stderr: a command's stdout (hal agent's run, hal mcp's protocol) stays its own
  if (global().json) io.err(`${JSON.stringify({ event: 'foxglove', url: server.url })}\n`);
  else io.err(`live view for Foxglove or Lichtblick: open ${open}\n`);
  return {
    hal: server.hal,
    url: server.url,
    close: async () => {
      if (closed) return;
      closed = true;
      const stats = server.stats();
      await server.close();
      if (stats.dropped === 0) return;
      const viewers = stats.drops.filter((d) => d.dropped > 0).length;
      io.err(
        global().json
          ? `${JSON.stringify({ event: 'foxglove-drops', dropped: stats.dropped, viewers })}\n`
          : `live view: ${stats.dropped} messages dropped for ${viewers} slow viewer(s)\n`,
      );
    },
  };
}
