// How every robot-facing command names the robot it talks to: exactly one of --sim, --udp,
// --serial, --ws, or NATS (--device and/or --nats). Parsing only; target-hal.ts builds the HAL.
import { Option } from 'commander';
import type { Command } from 'commander';
import { hexKeyArg, hostPortArg, hostPortText, integerArg, positiveArg, urlArg } from './values.js';
import type { NatsConnectOptions } from '@hal/nats';
import { BUILTIN_MAPS } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import { cameraToken, cameraTokenArg, cameraUrlArg } from './camera-options.js';
import { CliError } from './cli-error.js';
import { addNatsOptions, deviceIdArg, natsConnectOptions } from './nats-options.js';
import type { NatsCliOptions } from './nats-options.js';

/** A robot a command can talk to. */
export type Target =
  | { kind: 'sim'; map: BuiltinMapName; speed: number; deviceId?: string; calibration?: string }
  | {
      kind: 'udp';
      host: string;
      port: number;
      key?: string;
      timeScale: number;
      calibration?: string;
      camera?: TargetCamera;
    }
  | {
      kind: 'serial';
      path: string;
      baudRate?: number;
      key?: string;
      timeScale: number;
      calibration?: string;
      camera?: TargetCamera;
    }
  | { kind: 'ws'; url: string; token?: string }
  | { kind: 'nats'; deviceId?: string; nats: NatsConnectOptions };

/** A physical robot's ESP32-CAM: its base URL and token (`connection.cameraUrl`/`cameraToken`). */
export interface TargetCamera {
  url: string;
  token?: string;
}

export type TargetKind = Target['kind'];
export const TARGET_KINDS: readonly TargetKind[] = ['sim', 'udp', 'serial', 'ws', 'nats'];

/** The options as commander parses them. */
export interface TargetCliOptions extends NatsCliOptions {
  sim?: boolean;
  map?: BuiltinMapName;
  udp?: { host: string; port: number };
  serial?: string;
  baud?: number;
  key?: string;
  timeScale?: number;
  calibration?: string;
  cameraUrl?: string;
  cameraToken?: string;
  ws?: string;
  token?: string;
  device?: string;
  connectTimeout?: number;
}

/** Connecting gives up after this long by default, ms (a robot that is off is NOT_CONNECTED). */
export const DEFAULT_CONNECT_TIMEOUT_MS = 10_000;

/**
 * Adds the robot options of `kinds` to `command` (all five by default; `hal serve` takes only the
 * robots it can own: sim, udp and serial). NATS adds --device and the shared NATS options.
 */
export function addTargetOptions(
  command: Command,
  kinds: readonly TargetKind[] = TARGET_KINDS,
  /** Whether to offer `--calibration` (not to `hal calibrate`, which writes calibrations). */
  { calibration = true }: { calibration?: boolean } = {},
): Command {
  const has = (kind: TargetKind) => kinds.includes(kind);
  if (has('sim')) {
    command
      .addOption(new Option('--sim', 'an embedded simulator (in this process)'))
      .addOption(
        new Option('--map <name>', 'the simulator\'s map (with --sim; default "empty")').choices(
          Object.keys(BUILTIN_MAPS),
        ),
      );
  }
  if (has('udp')) {
    command.addOption(
      new Option(
        '--udp <host[:port]>',
        'a robot over WiFi UDP: HOST, HOST:PORT or [IPV6]:PORT (port 4210 by default)',
      ).argParser(hostPortArg('--udp')),
    );
  }
  if (has('serial')) {
    command
      .addOption(new Option('--serial <path>', 'a robot on a serial port'))
      .addOption(
        new Option('--baud <rate>', 'serial baud rate (with --serial)').argParser(
          integerArg('--baud', 1200, 4_000_000),
        ),
      );
  }
  if (has('udp') || has('serial')) {
    command.addOption(
      new Option(
        '--key <hex>',
        "the robot's pre-shared key (with --udp or --serial; default $HAL_KEY)",
      ).argParser(hexKeyArg('--key')),
    );
  }
  if (has('udp') || has('serial')) {
    command
      .addOption(
        new Option(
          '--camera-url <url>',
          "the robot's ESP32-CAM, http(s)://HOST[:PORT] (with --udp or --serial; its stream is /stream)",
        ).argParser(cameraUrlArg),
      )
      .addOption(
        new Option(
          '--camera-token <token>',
          "the camera's token, its CAM_TOKEN (with --camera-url; default $HAL_CAMERA_TOKEN)",
        ).argParser(cameraTokenArg('--camera-token')),
      );
  }
  if (has('sim') || has('udp') || has('serial')) {
    command.addOption(
      new Option(
        '--time-scale <factor>',
        "clock speed-up: the simulator's, or an emulated robot's --time-scale",
      ).argParser(positiveArg('--time-scale')),
    );
    if (calibration) {
      command.addOption(
        new Option(
          '--calibration <file|device-id>',
          "the wheels of this calibration file (from hal calibrate), or of this device's; default the robot's own",
        ),
      );
    }
  }
  if (has('ws')) {
    command
      .addOption(new Option('--ws <url>', 'a HAL served over WebSocket (hal serve --ws-port)'))
      .addOption(
        new Option('--token <secret>', "the WebSocket server's token (default $HAL_SERVE_TOKEN)"),
      );
  }
  if (has('nats')) {
    command.addOption(
      new Option(
        '--device <id>',
        'a device on NATS behind a gateway (with --nats or $NATS_URL; NATS without --device: the default device)',
      ).argParser(deviceIdArg),
    );
    addNatsOptions(command);
  }
  command.addOption(
    new Option('--connect-timeout <ms>', 'give up connecting after this long').argParser(
      integerArg('--connect-timeout', 100, 600_000),
    ),
  );
  return command;
}

const NATS_FLAGS: readonly (keyof TargetCliOptions)[] = [
  'nats',
  'natsUser',
  'natsPass',
  'natsToken',
  'natsCa',
  'natsCert',
  'natsKey',
];

function flag(name: string): string {
  return `--${name.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`)}`;
}

/** Refuses `names` that were given without the target they belong to. */
function onlyWith(
  options: TargetCliOptions,
  names: readonly (keyof TargetCliOptions)[],
  needs: string,
): void {
  for (const name of names) {
    if (options[name] !== undefined) {
      throw new CliError('USAGE', `"${flag(name)}" needs ${needs}`);
    }
  }
}

/**
 * Whether `options` name a robot at all: `hal agent` and `hal mcp` take the embedded simulator
 * when they do not.
 */
export function namesTarget(options: TargetCliOptions): boolean {
  return (
    options.sim === true ||
    options.udp !== undefined ||
    options.serial !== undefined ||
    options.ws !== undefined ||
    options.device !== undefined ||
    NATS_FLAGS.some((name) => options[name] !== undefined)
  );
}

/**
 * The one robot `options` name. A USAGE error when none or several are named, or when an option
 * belongs to another kind of robot (`--key` with `--sim`). `env` gives the NATS defaults.
 */
export function resolveTarget(
  options: TargetCliOptions,
  env: Readonly<Record<string, string | undefined>>,
  kinds: readonly TargetKind[] = TARGET_KINDS,
): Target {
  const natsGiven =
    options.device !== undefined || NATS_FLAGS.some((name) => options[name] !== undefined);
  const named: [TargetKind, string][] = [];
  if (options.sim === true) named.push(['sim', '--sim']);
  if (options.udp !== undefined) named.push(['udp', '--udp']);
  if (options.serial !== undefined) named.push(['serial', '--serial']);
  if (options.ws !== undefined) named.push(['ws', '--ws']);
  if (natsGiven && kinds.includes('nats')) named.push(['nats', '--device/--nats']);
  const choices = kinds
    .map(
      (kind) =>
        ({ sim: '--sim', udp: '--udp', serial: '--serial', ws: '--ws', nats: '--device' })[kind],
    )
    .join(', ');
  if (named.length === 0) {
    throw new CliError('USAGE', `name the robot: one of ${choices}`);
  }
  if (named.length > 1) {
    throw new CliError(
      'USAGE',
      `name one robot, not ${named.map(([, f]) => f).join(' and ')} (one of ${choices})`,
    );
  }
  const kind = named[0]![0];
  if (kind !== 'sim') onlyWith(options, ['map'], '--sim');
  if (kind !== 'serial') onlyWith(options, ['baud'], '--serial');
  if (kind !== 'udp' && kind !== 'serial')
    onlyWith(options, ['key', 'cameraUrl', 'cameraToken'], '--udp or --serial');
  if (options.cameraUrl === undefined) onlyWith(options, ['cameraToken'], '--camera-url');
  if (kind === 'ws' || kind === 'nats')
    onlyWith(options, ['timeScale', 'calibration'], '--sim, --udp or --serial');
  const keyText = options.key ?? env['HAL_KEY'];
  const key =
    keyText === undefined || keyText === '' || (kind !== 'udp' && kind !== 'serial')
      ? {}
      : { key: hexKeyArg(options.key === undefined ? '$HAL_KEY' : '--key')(keyText) };
  const calibration = options.calibration === undefined ? {} : { calibration: options.calibration };
  const camera = physicalCamera(options, env, kind);
  switch (kind) {
    case 'sim':
      return { kind, map: options.map ?? 'empty', speed: options.timeScale ?? 1, ...calibration };
    case 'udp':
      return {
        kind,
        ...options.udp!,
        ...key,
        timeScale: options.timeScale ?? 1,
        ...calibration,
        ...camera,
      };
    case 'serial':
      return {
        kind,
        path: options.serial!,
        ...(options.baud === undefined ? {} : { baudRate: options.baud }),
        ...key,
        timeScale: options.timeScale ?? 1,
        ...calibration,
        ...camera,
      };
    case 'ws': {
      const token = options.token ?? env['HAL_SERVE_TOKEN'];
      return {
        kind,
        url: urlArg('--ws', ['ws:', 'wss:'])(options.ws!),
        ...(token === undefined ? {} : { token }),
      };
    }
    case 'nats':
      return {
        kind,
        ...(options.device === undefined ? {} : { deviceId: options.device }),
        nats: natsConnectOptions(options, env),
      };
  }
}

/** The camera of a physical robot: `--camera-url` with its token (or $HAL_CAMERA_TOKEN's). */
function physicalCamera(
  options: TargetCliOptions,
  env: Readonly<Record<string, string | undefined>>,
  kind: TargetKind,
): { camera?: TargetCamera } {
  if (options.cameraUrl === undefined || (kind !== 'udp' && kind !== 'serial')) return {};
  const token = cameraToken(options.cameraToken, env);
  return { camera: { url: options.cameraUrl, ...(token === undefined ? {} : { token }) } };
}

/** A short name for the target, for messages (`udp 127.0.0.1:4210`). */
export function describeTarget(target: Target): string {
  switch (target.kind) {
    case 'sim':
      return `simulator (map ${target.map})`;
    case 'udp':
      return `robot at udp ${hostPortText(target)}`;
    case 'serial':
      return `robot on ${target.path}`;
    case 'ws':
      return `HAL at ${target.url}`;
    case 'nats':
      return `device ${target.deviceId ?? '(default)'} on NATS ${[target.nats.servers].flat().join(',')}`;
  }
}

/**
 * The options that name `target` again on a command line, for hints (`--udp 127.0.0.1:4210`);
 * secrets are shown as placeholders, never echoed. Undefined for the embedded simulator, which
 * lives only as long as its command.
 */
export function targetArgs(target: Target): string | undefined {
  switch (target.kind) {
    case 'sim':
      return undefined;
    case 'udp':
    case 'serial': {
      const where =
        target.kind === 'udp'
          ? `--udp ${hostPortText(target)}`
          : `--serial ${target.path}${target.baudRate === undefined ? '' : ` --baud ${target.baudRate}`}`;
      const key = target.key === undefined ? '' : ' --key <hex>';
      const scale = target.timeScale === 1 ? '' : ` --time-scale ${target.timeScale}`;
      const camera =
        target.camera === undefined
          ? ''
          : ` --camera-url ${target.camera.url}${target.camera.token === undefined ? '' : ' --camera-token <token>'}`;
      return `${where}${key}${scale}${camera}`;
    }
    case 'ws':
      return `--ws ${target.url}`;
    case 'nats': {
      const device = target.deviceId === undefined ? '' : `--device ${target.deviceId} `;
      return `${device}--nats ${[target.nats.servers].flat().join(',')}`;
    }
  }
}
