// `hal emulate`'s options, and the cube-emulator flags they become.
import { DEFAULT_UDP_PORT } from '@hal/physical';
import { ROBOT_SETTINGS } from '@hal/types';
import { Option } from 'commander';
import type { Command } from 'commander';
import { ipv4Arg } from '../discover/options.js';
import { cameraTokenArg } from '../camera-options.js';
import { hexKeyArg, integerArg, numberArg, portArg } from '../values.js';
import { deviceIdArg } from '../nats-options.js';

/** The robot's host timeout range, from the one settings table (the firmware's own). */
const HOST_TIMEOUT = ROBOT_SETTINGS.find((s) => s.key === 'hostTimeoutMs')!;

export interface EmulateCliOptions {
  udpPort: number;
  bind: string;
  deviceId: string;
  key?: string;
  insecure: boolean;
  timeScale?: number;
  hostTimeoutMs?: number;
  pty: boolean;
  announce: boolean;
  emulator?: string;
  interface?: string;
  /** The camera's port (`--camera` alone: {@link DEFAULT_CAMERA_PORT}), when it is served. */
  camera?: number;
  /** The world file the camera sees (default an empty arena). */
  world?: string;
  /** The token the camera asks for (default $HAL_CAMERA_TOKEN). */
  cameraToken?: string;
}

/** The port `--camera` serves on when it names none. */
export const DEFAULT_CAMERA_PORT = 8080;

/** How often cube-emulator reports the wheels for the camera, ms (a 10 fps camera: 5 a frame). */
export const WHEEL_REPORT_MS = 20;

export function addEmulateOptions(command: Command): Command {
  return command
    .addOption(
      new Option('--udp-port <port>', 'UDP port (0 = a free one)')
        .argParser(portArg('--udp-port', { anyFree: true }))
        .default(DEFAULT_UDP_PORT),
    )
    .addOption(
      new Option(
        '--bind <address>',
        'IPv4 address to listen on; not loopback needs --key or --insecure',
      )
        .argParser(ipv4Arg('--bind'))
        .default('127.0.0.1'),
    )
    .addOption(
      new Option('--device-id <id>', 'the robot device id (announced, and reported by hello)')
        .argParser(deviceIdArg)
        .default('cube-emulator'),
    )
    .addOption(
      new Option('--key <hex>', 'pre-shared key: requests must be MACed').argParser(
        hexKeyArg('--key'),
      ),
    )
    .addOption(new Option('--insecure', 'allow a non-loopback --bind without --key').default(false))
    .addOption(
      new Option('--time-scale <x>', "run the robot's clock x times faster").argParser(
        numberArg('--time-scale', { min: 0, aboveMin: true, max: 1000 }),
      ),
    )
    .addOption(
      new Option(
        '--host-timeout-ms <ms>',
        `host timeout, ${HOST_TIMEOUT.min}..${HOST_TIMEOUT.max}`,
      ).argParser(integerArg('--host-timeout-ms', HOST_TIMEOUT.min, HOST_TIMEOUT.max)),
    )
    .option('--no-pty', 'do not open a pseudo-terminal for the serial link')
    .option('--no-announce', 'do not announce the robot with mDNS')
    .addOption(
      new Option(
        '--emulator <path>',
        'the cube-emulator program (default $CUBE_EMULATOR, else built)',
      ),
    )
    .addOption(
      new Option('--interface <address>', 'IPv4 address of the interface to announce on').argParser(
        ipv4Arg('--interface'),
      ),
    )
    .addOption(
      new Option(
        '--camera [port]',
        "also serve the ESP32-CAM's HTTP interface (/stream, /status) on the --bind address, rendered from the robot's true pose (0 = a free port)",
      )
        .preset(String(DEFAULT_CAMERA_PORT))
        .argParser(portArg('--camera', { anyFree: true })),
    )
    .addOption(
      new Option(
        '--world <file>',
        'the world the camera sees, in the eval task format ({ map, start, objects }; with --camera; default an empty arena)',
      ),
    )
    .addOption(
      new Option(
        '--camera-token <token>',
        "the token the camera asks for, as the sketch's CAM_TOKEN (with --camera; default $HAL_CAMERA_TOKEN)",
      ).argParser(cameraTokenArg('--camera-token')),
    );
}

/** The cube-emulator command line for these options. */
export function emulatorArgs(o: EmulateCliOptions): string[] {
  const args = ['--udp-port', String(o.udpPort), '--bind', o.bind, '--device-id', o.deviceId];
  if (o.key !== undefined) args.push('--key', o.key);
  if (o.insecure) args.push('--insecure');
  if (o.timeScale !== undefined) args.push('--time-scale', String(o.timeScale));
  if (o.hostTimeoutMs !== undefined) args.push('--host-timeout-ms', String(o.hostTimeoutMs));
  if (!o.pty) args.push('--no-pty');
  if (o.camera !== undefined) args.push('--report-wheels-ms', String(WHEEL_REPORT_MS));
  return args;
}
