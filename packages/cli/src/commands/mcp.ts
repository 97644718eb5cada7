// `hal mcp`: the MCP server of @hal/mcp for one robot (any the target options name: the embedded
// simulator unless one is named, maybe in a --world), offering the tools of --tools, over stdio or
// streamable HTTP, until Ctrl-C (or, on stdio, until stdin ends). Then the robot is cleaned up,
// which stops its motors. Its messages go to stderr: on stdio, stdout carries the protocol.
import { Writable } from 'node:stream';
import type { Readable } from 'node:stream';
import { Command } from 'commander';
import { StdioServerTransport } from '@modelcontextprotocol/sdk/server/stdio.js';
import { createRobotMcpServer, policyText, RobotEvents, serveHttp } from '@hal/mcp';
import type { RobotWorld } from '@hal/mcp';
import { recordHal } from '@hal/recorder';
import { SimulationHAL } from '@hal/simulation';
import { CAPABILITIES, hasCapability } from '@hal/types';
import { CliError } from '../cli-error.js';
import type { CliIO } from '../io.js';
import { listenError } from '../listen-error.js';
import { addFoxgloveOptions, foxglovePlan, startLiveView } from '../foxglove/live-view.js';
import type { FoxgloveCliOptions, LiveView } from '../foxglove/live-view.js';
import { addGuardOptions, guardFromOptions, recordGuard } from '../guard-options.js';
import { seeingFrom } from '../seeing.js';
import type { GuardCliOptions } from '../guard-options.js';
import { cliLogger } from '../logger.js';
import { readLookWorld, openWorldSimulator } from '../look/look-world.js';
import { addMcpOptions, mcpOptions } from '../mcp/options.js';
import type { McpCliOptions } from '../mcp/options.js';
import { mcpEventSources, tapLog } from '../mcp/event-sources.js';
import { offeredTools } from '../mcp/offered-tools.js';
import { openRecordingFile } from '../output-place.js';
import { openTarget } from '../target-hal.js';
import type { OpenedHal } from '../target-hal.js';
import { aborted } from '../wait.js';
import type { RegisterCommand } from './context.js';

/** Resolves when `stdin` ends (the MCP client went away) or `signal` is aborted. */
function clientGone(stdin: Readable, signal: AbortSignal): Promise<void> {
  return Promise.race([
    aborted(signal),
    new Promise<void>((resolve) => {
      if (stdin.readableEnded) resolve();
      stdin.once('end', () => resolve());
      stdin.once('close', () => resolve());
    }),
  ]);
}

/** stdout as the stream the SDK's transport writes, through the CLI's output. */
function outStream(io: CliIO): Writable {
  return new Writable({
    write(chunk: Buffer | string, _encoding, done) {
      io.out(chunk.toString());
      done();
    },
  });
}

export const registerMcp: RegisterCommand = (program, { io, global }) => {
  const command = new Command('mcp').description(
    'MCP server for a robot: the HAL tools or the skills (--tools), its state, capabilities and ' +
      'map as resources (the robot the target options name; the embedded simulator when none is named)',
  );
  addMcpOptions(command);
  addGuardOptions(command);
  addFoxgloveOptions(command);
  command.action(async (raw: McpCliOptions & GuardCliOptions & FoxgloveCliOptions) => {
    const options = mcpOptions(raw, io.env);
    // a live view that cannot be served as asked is refused before the robot is touched
    const foxglove = foxglovePlan(raw, io.env);
    const { target } = options;
    const stdin = io.stdin as Readable | undefined;
    if (!options.http && stdin === undefined) {
      throw new CliError('USAGE', 'MCP over stdio needs a standard input: give --http');
    }
    // a world or a file that cannot be used is refused before the robot is touched
    const world = options.world === undefined ? undefined : await readLookWorld(options.world);
    const recorder =
      options.record === undefined
        ? undefined
        : await openRecordingFile(
            { option: '--record', path: options.record, overwrite: options.overwrite },
            { logger: cliLogger(io, false) },
          );
    const sampling = new AbortController();
    let opened: OpenedHal;
    try {
      opened =
        world !== undefined && target.kind === 'sim'
          ? await openWorldSimulator(world, io, {
              speed: target.speed,
              ...(target.calibration === undefined ? {} : { calibration: target.calibration }),
            })
          : await openTarget(target, io, {
              role: 'control',
              ...(options.connectTimeoutMs === undefined
                ? {}
                : { connectTimeoutMs: options.connectTimeoutMs }),
            });
    } catch (error) {
      await recorder?.close().catch(() => undefined);
      throw error;
    }
    const robot = opened.hal;
    // the map is known of the embedded simulator only
    const arena: RobotWorld = robot instanceof SimulationHAL ? { map: () => robot.world.map } : {};
    // the guard sits between the leash (the executor) and the robot
    const { hal: guarded, guard } = guardFromOptions(robot, raw, io, false, target);
    recordGuard(guard, recorder);
    // scan answers from the range sensors and the camera, as the robot can know
    const { hal: seeing, perception } = seeingFrom(guarded, robot, recorder, target);
    const recorded =
      recorder === undefined
        ? seeing
        : recordHal(seeing, recorder, {
            signal: sampling.signal,
            deviceId: opened.deviceId,
            ...(world !== undefined
              ? { map: { world: world.file } }
              : target.kind === 'sim'
                ? { map: { name: target.map } }
                : {}),
          });
    let live: LiveView | undefined;
    let stopEvents = (): void => undefined;
    let close: () => Promise<void> = async () => undefined;
    try {
      // a viewer watches what the MCP client does, and may drive under the same leash
      live = await startLiveView(
        recorded,
        foxglove,
        { io, global },
        {
          deviceId: opened.deviceId,
          leash: options.leash,
          ...(perception === undefined ? {} : { perception }),
        },
      );
      // the log lines the tools write also go to the MCP client, as logging notifications
      const { hal, logs } = tapLog(live.hal);
      // once for the run, as the tools are: what happens to the robot, for every server of it;
      // watched on the robot itself, so that a recording does not hold every look
      const events = new RobotEvents(robot, mcpEventSources(robot, guard, logs));
      stopEvents = events.open();
      // once for the run: over HTTP each session has a server of its own, the skills one memory
      const offered = offeredTools(hal, {
        profile: options.profile,
        leash: options.leash,
        approve: options.approve,
        ...(options.timeoutMs === undefined ? {} : { timeoutMs: options.timeoutMs }),
      });
      const create = () =>
        createRobotMcpServer(hal, offered, arena, {
          approve: options.approve,
          approvalTimeoutMs: options.approvalTimeoutMs,
          events,
          monitor: robot,
        });
      io.err(
        options.approve === 'none'
          ? 'hal mcp: no one approves motions (--approve none): they run as the leash allows\n'
          : `hal mcp: the MCP client's user approves motions (--approve ${policyText(options.approve)}), ` +
              `${options.approvalTimeoutMs / 1000} s to answer; a client without elicitation has every motion refused\n`,
      );
      const serving = `${hal.mode} robot, ${options.profile} tools`;
      if (
        options.profile !== 'primitives' &&
        !hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.camera)
      ) {
        io.err(
          'hal mcp: the robot has no camera: the skills that look (look, find, go_to or face a named thing, explore) cannot see\n',
        );
      }
      if (options.http) {
        // with sessions: a client's server can ask it, and tell it of progress and events
        const endpoint = await serveHttp(create, {
          host: options.host,
          port: options.port,
          sessions: true,
          ...(options.token === undefined ? {} : { token: options.token }),
        }).catch((error: unknown) => {
          throw listenError(error, {
            host: options.host,
            port: options.port,
            portOption: '--port',
            hostOption: '--host',
          });
        });
        close = endpoint.close;
        io.err(`hal mcp: ${serving}, MCP over HTTP at ${endpoint.url}\n`);
        await aborted(io.signal);
      } else {
        const server = create();
        await server.connect(new StdioServerTransport(stdin, outStream(io)));
        close = () => server.close();
        io.err(`hal mcp: ${serving}, MCP over stdio\n`);
        await clientGone(stdin!, io.signal);
      }
    } finally {
      await close().catch(() => undefined);
      stopEvents();
      // the live view closes before the robot is let go
      await live?.close().catch(() => undefined);
      // the HAL's own cleanup, through the recorder when there is one (it stops the motors)
      if (recorder !== undefined) await recorded.cleanup().catch(() => undefined);
      await opened.close();
      sampling.abort();
      if (recorder !== undefined) {
        const stats = await recorder.close();
        io.err(
          `hal mcp: recorded ${stats.written} messages to ${options.record}${stats.dropped > 0 ? `, ${stats.dropped} dropped` : ''}\n`,
        );
      }
    }
  });
  program.addCommand(command);
};
