// `hal serve`: owns one robot's HAL (--sim, --udp or --serial) and serves it on NATS (the
// gateway of @hal/nats), on WebSocket (serveHal of @hal/remote), as a live view for Foxglove
// (--foxglove), or any of them together, until Ctrl-C. Then it stops serving and cleans the HAL
// up, which stops a physical robot.
import { Command, Option } from 'commander';
import { TAFY_NODE_TYPE } from '@hal/discovery';
import type { TafyNodeAnnouncer } from '@hal/discovery';
import { openConnection, refuseServedTwice, serveHalOnNats } from '@hal/nats';
import { GuardedHAL } from '@hal/perception';
import { recordHal } from '@hal/recorder';
import type { RecorderStats } from '@hal/recorder';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { FoxgloveServeOptions } from '@hal/foxglove';
import type { HalGateway } from '@hal/nats';
import { integerArg } from '../values.js';
import { checkBinding, serveHal } from '@hal/remote/server';
import type { HalServer } from '@hal/remote/server';
import { CliError } from '../cli-error.js';
import { emit, progress } from '../io.js';
import type { CliIO } from '../io.js';
import { addNatsOptions, deviceIdArg } from '../nats-options.js';
import { announceGateway } from '../serve/announce-node.js';
import { allowOriginArg } from '../serve/allow-origin.js';
import { servePlan, servedSubjects } from '../serve/where.js';
import type { ServeCliOptions, ServePlan } from '../serve/where.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { Target, TargetCliOptions } from '../target.js';
import { listenError } from '../listen-error.js';
import { addFoxgloveOptions, foxglovePlan, startLiveView } from '../foxglove/live-view.js';
import type { FoxgloveCliOptions, LiveView } from '../foxglove/live-view.js';
import { addGuardOptions, guardFromOptions, recordGuard } from '../guard-options.js';
import type { GuardCliOptions } from '../guard-options.js';
import { cliLogger } from '../logger.js';
import { addOverwriteOption, openRecordingFile } from '../output-place.js';
import { openTarget } from '../target-hal.js';
import { aborted } from '../wait.js';
import type { CommandContext, RegisterCommand } from './context.js';

const SERVED_KINDS = ['sim', 'udp', 'serial'] as const;

/** The NATS connection `hal serve` opens (and closes) itself. */
type NatsConnection = Awaited<ReturnType<typeof openConnection>>;

export const registerServe: RegisterCommand = (program, { io, global }) => {
  const command = new Command('serve')
    .description(
      'serve one robot (--sim, --udp or --serial) on NATS, WebSocket and/or as a Foxglove live view',
    )
    .addOption(
      new Option(
        '--device <id>',
        "the id it is served as (NATS subjects, WebSocket hello; default the robot's own)",
      ).argParser(deviceIdArg),
    )
    .addOption(
      new Option(
        '--no-default-device',
        "do not answer the spec's bare subjects (hal.v1.motor...); for all but one device of a fleet",
      ),
    )
    .addOption(
      new Option(
        '--no-mdns',
        "do not announce the NATS gateway by mDNS (as the spec's _tafynode._tcp)",
      ),
    )
    .addOption(
      new Option(
        '--state-rate <hz>',
        'state messages per second (NATS 10..100, 0: none; default NATS 20, WebSocket 10)',
      ).argParser(integerArg('--state-rate', 0, 100)),
    )
    .addOption(
      new Option(
        '--ws-port <port>',
        'serve on WebSocket on this TCP port (0: any free one)',
      ).argParser(integerArg('--ws-port', 0, 65_535)),
    )
    .addOption(
      new Option(
        '--host <address>',
        'WebSocket address to listen on (default 127.0.0.1; not loopback: --token needed)',
      ),
    )
    .addOption(
      new Option(
        '--token <secret>',
        'token WebSocket clients must present, 16+ characters (default $HAL_SERVE_TOKEN)',
      ),
    )
    .addOption(
      new Option(
        '--allow-origin <origin>',
        'trust web pages from this origin on WebSocket without a token, e.g. https://app.example (repeatable; pages from this machine are trusted)',
      ).argParser(allowOriginArg),
    )
    .addOption(
      new Option(
        '--heartbeat-timeout <ms>',
        'drop a silent WebSocket client (and stop its motion) after this long (default 2000)',
      ).argParser(integerArg('--heartbeat-timeout', 100, 10_000)),
    );
  command.addOption(
    new Option(
      '--record <file>',
      "record the served robot's run (every call from every client) into this MCAP file",
    ),
  );
  addOverwriteOption(command, 'the --record file');
  addNatsOptions(command);
  addFoxgloveOptions(command);
  addGuardOptions(command);
  addTargetOptions(command, SERVED_KINDS);
  command.action(async (options: ServeOptions) => {
    const foxglove = foxglovePlan(options, io.env);
    const plan = planOf(options, io.env, foxglove);
    // the robot options only (--device here names the served id, not a NATS robot to reach)
    const target = resolveTarget(options, io.env, SERVED_KINDS);
    if (plan.ws !== undefined) checkBinding(plan.ws.host, plan.ws.token); // before touching the robot
    // NATS first: a device already served is refused before the robot is opened (which would
    // take a physical robot's session from the gateway serving it)
    const nc = plan.nats === undefined ? undefined : await openConnection(plan.nats.connect);
    try {
      if (nc !== undefined && plan.nats !== undefined) {
        await refuseServedTwice(nc, {
          ...(options.device === undefined ? {} : { deviceId: options.device }),
          defaultDevice: plan.nats.defaultDevice,
        });
      }
      await serveTarget({ io, global }, options, { ...plan, foxglove }, target, nc);
    } finally {
      await nc?.close().catch(() => undefined);
    }
  });
  program.addCommand(command);
};

type ServeOptions = ServeCliOptions & TargetCliOptions & GuardCliOptions & FoxgloveCliOptions;

/**
 * Where to serve. --foxglove alone is a door of its own; beside it, the WebSocket and NATS
 * options keep their rules (a --host without --ws-port is refused as before).
 */
function planOf(
  options: ServeOptions,
  env: Readonly<Record<string, string | undefined>>,
  foxglove: FoxgloveServeOptions | undefined,
): ServePlan {
  if (options.nats !== undefined || options.wsPort !== undefined) return servePlan(options, env);
  // neither NATS nor WebSocket: the NATS options without --nats are refused there first, as
  // before (the WebSocket plan it makes for the check is not used)
  servePlan({ ...options, wsPort: 0 }, env);
  if (foxglove === undefined) {
    throw new CliError(
      'USAGE',
      'say where to serve: --nats <servers> for NATS, --ws-port <port> for WebSocket, --foxglove [port] for a live view, or several',
    );
  }
  for (const [value, name] of [
    [options.host, '--host'],
    [options.token, '--token'],
    [options.allowOrigin, '--allow-origin'],
    [options.heartbeatTimeout, '--heartbeat-timeout'],
  ] as const) {
    if (value !== undefined) throw new CliError('USAGE', `"${name}" needs --ws-port`);
  }
  return {};
}

/** Opens the robot, serves it until Ctrl-C, then stops serving and lets it go. */
async function serveTarget(
  { io, global }: CommandContext,
  options: ServeOptions,
  plan: ServePlan & { foxglove: FoxgloveServeOptions | undefined },
  target: Target,
  nc: NatsConnection | undefined,
): Promise<void> {
  // a file that cannot be written is refused before the robot is touched
  const recording =
    options.record === undefined
      ? undefined
      : await startRecording(options.record, options.overwrite === true, io, global().json);
  const opened = await openTarget(target, io, {
    json: global().json,
    ...(options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout }),
    ...(options.device === undefined ? {} : { deviceId: options.device }),
  }).catch(async (error: unknown) => {
    await recording?.close();
    throw error;
  });
  // the guard stops what the network drives before an obstacle ahead
  const { hal: guarded } = guardFromOptions(opened.hal, options, io, global().json);
  const recorded = recording?.wrap(guarded, options.device ?? opened.deviceId) ?? guarded;
  let live: LiveView | undefined;
  let gateway: HalGateway | undefined;
  let server: HalServer | undefined;
  let announcer: TafyNodeAnnouncer | undefined;
  try {
    const deviceId = options.device ?? opened.deviceId;
    // the view sees every door's calls: the other doors serve its tapped HAL
    live = await startLiveView(recorded, plan.foxglove, { io, global }, { deviceId });
    const hal = live.hal;
    const liveUrl = live.url;
    if (plan.nats !== undefined && nc !== undefined) {
      try {
        deviceIdArg(deviceId);
      } catch {
        throw new CliError(
          'USAGE',
          `the robot's id "${deviceId}" is not a NATS subject token: give --device <id>`,
        );
      }
      gateway = await serveHalOnNats(hal, {
        connection: nc,
        deviceId,
        defaultDevice: plan.nats.defaultDevice,
        stateRateHz: plan.nats.stateRateHz,
      });
    }
    if (plan.ws !== undefined) {
      const ws = plan.ws;
      server = await serveHal(hal, {
        ...ws,
        deviceId,
        logger: cliLogger(io, global().json),
      }).catch((error: unknown) => {
        throw listenError(error, {
          host: ws.host,
          port: ws.port,
          portOption: '--ws-port',
          hostOption: '--host',
        });
      });
    }
    let mdns: { service: string; name: string } | { error: string } | undefined;
    if (plan.nats !== undefined && options.mdns !== false) {
      const announced = await announceGateway({
        deviceId,
        caps: hal.getDeviceInfo().capabilities,
        servers: [plan.nats.connect.servers].flat(),
      });
      if (typeof announced === 'string') mdns = { error: announced };
      else {
        announcer = announced;
        mdns = { service: TAFY_NODE_TYPE, name: announced.name };
      }
    }
    const serving = {
      event: 'serving',
      device: deviceId,
      mode: hal.mode,
      ...(plan.nats === undefined
        ? {}
        : {
            nats: {
              servers: [plan.nats.connect.servers].flat(),
              subjects: servedSubjects(deviceId, plan.nats.defaultDevice),
            },
          }),
      ...(server === undefined ? {} : { ws: { url: server.url } }),
      ...(liveUrl === undefined ? {} : { foxglove: { url: liveUrl } }),
      ...(mdns === undefined ? {} : { mdns }),
    };
    emit(io, global(), serving, () =>
      [
        `serving ${deviceId} (${hal.mode})`,
        ...(serving.nats === undefined
          ? []
          : [`  nats ${serving.nats.servers.join(',')}: ${serving.nats.subjects.join(', ')}`]),
        ...(server === undefined ? [] : [`  listening ${server.url}`]),
        ...(liveUrl === undefined ? [] : [`  foxglove ${liveUrl}`]),
        ...(mdns === undefined
          ? []
          : 'error' in mdns
            ? [`  not announced by mDNS: ${mdns.error}`]
            : [`  announced by mDNS as ${mdns.name}.${mdns.service}.local`]),
      ].join('\n'),
    );
    progress(io, global(), 'Ctrl-C stops serving (and stops the robot)');
    await aborted(io.signal);
    progress(io, global(), 'stopping');
  } finally {
    await announcer?.stop().catch(() => undefined);
    await server?.close().catch(() => undefined);
    await gateway?.close().catch(() => undefined);
    await live?.close().catch(() => undefined);
    await opened.close();
  }
  const written = await recording?.close();
  emit(
    io,
    global(),
    { event: 'stopped', ...(written === undefined ? {} : { recording: written }) },
    () =>
      written === undefined
        ? 'stopped'
        : `stopped; recorded ${written.written} messages to ${written.file}${written.dropped > 0 ? `, ${written.dropped} dropped` : ''}`,
  );
}

/** --record: the served HAL, recorded into `file`, and how to finish the file. */
async function startRecording(
  file: string,
  overwrite: boolean,
  io: CliIO,
  json: boolean,
): Promise<{
  wrap(served: HardwareAbstractionLayer, deviceId: string): HardwareAbstractionLayer;
  close(): Promise<RecorderStats & { file: string }>;
}> {
  const log = cliLogger(io, json);
  const recorder = await openRecordingFile(
    { option: '--record', path: file, overwrite },
    { logger: log },
  );
  const sampling = new AbortController();
  return {
    wrap: (served, deviceId) => {
      // the guard's stops beside the calls
      if (served instanceof GuardedHAL) recordGuard(served, recorder);
      return recordHal(served, recorder, { signal: sampling.signal, deviceId });
    },
    close: async () => {
      sampling.abort();
      return { file, ...(await recorder.close()) };
    },
  };
}
