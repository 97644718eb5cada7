import { Command } from 'commander';
import { describe, expect, it } from 'vitest';
import { CliError } from './cli-error.js';
import { addTargetOptions, describeTarget, resolveTarget, targetArgs } from './target.js';
import type { TargetCliOptions, TargetKind } from './target.js';

function parse(argv: string[], kinds?: readonly TargetKind[], env = {}) {
  const command = addTargetOptions(new Command('x').exitOverride(), kinds);
  command.configureOutput({ writeErr: () => undefined });
  command.parse(argv, { from: 'user' });
  return resolveTarget(command.opts<TargetCliOptions>(), env, kinds);
}

function usage(argv: string[], kinds?: readonly TargetKind[]): string {
  try {
    parse(argv, kinds);
  } catch (error) {
    if (error instanceof CliError && error.code === 'USAGE') return error.message;
    if (error instanceof Error && 'exitCode' in error) return error.message;
    throw error;
  }
  throw new Error(`${argv.join(' ')} was accepted`);
}

describe('naming the robot', () => {
  it('reads each kind of robot with its defaults', () => {
    expect(parse(['--sim'])).toEqual({ kind: 'sim', map: 'empty', speed: 1 });
    expect(parse(['--sim', '--map', 'maze', '--time-scale', '5'])).toEqual({
      kind: 'sim',
      map: 'maze',
      speed: 5,
    });
    expect(parse(['--udp', '192.168.4.1', '--key', 'a1b2'])).toEqual({
      kind: 'udp',
      host: '192.168.4.1',
      port: 4210,
      key: 'a1b2',
      timeScale: 1,
    });
    expect(parse(['--serial', '/dev/ttyUSB0', '--baud', '115200'])).toEqual({
      kind: 'serial',
      path: '/dev/ttyUSB0',
      baudRate: 115200,
      timeScale: 1,
    });
    expect(parse(['--ws', 'ws://10.0.0.2:8765', '--token', 'sixteen-characters'])).toEqual({
      kind: 'ws',
      url: 'ws://10.0.0.2:8765',
      token: 'sixteen-characters',
    });
  });

  it('reads an IPv6 robot in brackets, as every command does, and names it so again', () => {
    const target = parse(['--udp', '[fe80::1]:4300']);
    expect(target).toEqual({ kind: 'udp', host: 'fe80::1', port: 4300, timeScale: 1 });
    expect(describeTarget(target)).toBe('robot at udp [fe80::1]:4300');
    expect(targetArgs(target)).toBe('--udp [fe80::1]:4300');
  });

  it("takes a physical robot's key from $HAL_KEY when --key is not given, and checks it", () => {
    expect(parse(['--udp', 'cube'], undefined, { HAL_KEY: '00ff' })).toMatchObject({ key: '00ff' });
    expect(parse(['--udp', 'cube', '--key', 'abcd'], undefined, { HAL_KEY: '00ff' })).toMatchObject(
      { key: 'abcd' },
    );
    // not for a robot that takes no key
    expect(parse(['--sim'], undefined, { HAL_KEY: '00ff' })).toEqual({
      kind: 'sim',
      map: 'empty',
      speed: 1,
    });
    expect(() => parse(['--udp', 'cube'], undefined, { HAL_KEY: 'xyz' })).toThrow(
      '"$HAL_KEY" must be 1..64 bytes written as hex',
    );
  });

  it("names a physical robot's camera, its token from --camera-token or $HAL_CAMERA_TOKEN", () => {
    const url = 'http://127.0.0.1:8080';
    expect(parse(['--udp', 'cube', '--camera-url', url])).toEqual({
      kind: 'udp',
      host: 'cube',
      port: 4210,
      timeScale: 1,
      camera: { url },
    });
    const fromEnv = parse(['--serial', '/dev/ttyUSB0', '--camera-url', url], undefined, {
      HAL_CAMERA_TOKEN: 'from-env',
    });
    expect(fromEnv).toMatchObject({ camera: { url, token: 'from-env' } });
    const given = parse(
      ['--udp', 'cube', '--camera-url', url, '--camera-token', 'given'],
      undefined,
      {
        HAL_CAMERA_TOKEN: 'from-env',
      },
    );
    expect(given).toMatchObject({ camera: { url, token: 'given' } });
    // the token is never shown again
    expect(targetArgs(given)).toBe(`--udp cube:4210 --camera-url ${url} --camera-token <token>`);
    // $HAL_CAMERA_TOKEN alone names no camera
    expect(parse(['--udp', 'cube'], undefined, { HAL_CAMERA_TOKEN: 'x' })).not.toHaveProperty(
      'camera',
    );
    expect(() =>
      parse(['--udp', 'cube', '--camera-url', url], undefined, { HAL_CAMERA_TOKEN: 'a b' }),
    ).toThrow('"$HAL_CAMERA_TOKEN" must be 1..128 of A-Z a-z 0-9 - . _ ~');
  });

  it('reaches a NATS device by --device, or the default device with --nats alone', () => {
    expect(parse(['--device', 'cube-01'], undefined, { NATS_URL: 'nats://hub:4222' })).toEqual({
      kind: 'nats',
      deviceId: 'cube-01',
      nats: { servers: ['nats://hub:4222'], name: 'hal-cli' },
    });
    expect(parse(['--nats', 'nats://127.0.0.1:4333'])).toEqual({
      kind: 'nats',
      nats: { servers: ['nats://127.0.0.1:4333'], name: 'hal-cli' },
    });
  });

  it.each([
    [[], /name the robot: one of --sim, --udp, --serial, --ws, --device/],
    [['--sim', '--udp', 'a'], /name one robot, not --sim and --udp/],
    [['--ws', 'ws://a', '--device', 'd'], /not --ws and --device\/--nats/],
    [['--udp', 'a', '--map', 'maze'], /"--map" needs --sim/],
    [['--sim', '--key', 'a1b2'], /"--key" needs --udp or --serial/],
    [['--udp', 'a', '--baud', '9600'], /"--baud" needs --serial/],
    [['--ws', 'ws://a', '--time-scale', '2'], /"--time-scale" needs --sim, --udp or --serial/],
    [['--ws', 'http://a'], /"--ws" must be a ws:\/\/ or wss:\/\/ URL/],
    [['--udp', 'host:99999'], /"--udp" must be HOST, HOST:PORT or \[IPV6\]:PORT/],
    [['--device', 'a.b'], /a device id is 1-64 letters/],
    [['--sim', '--map', 'moon'], /Allowed choices are empty, obstacles, maze, room/],
    [['--sim', '--camera-url', 'http://a'], /"--camera-url" needs --udp or --serial/],
    [['--udp', 'a', '--camera-token', 'abc'], /"--camera-token" needs --camera-url/],
    [
      ['--udp', 'a', '--camera-url', 'rtsp://a'],
      /"--camera-url" must be a http:\/\/ or https:\/\/ URL/,
    ],
    [
      ['--udp', 'a', '--camera-url', 'cam'],
      /"--camera-url" must be a http:\/\/ or https:\/\/ URL, got "cam"/,
    ],
    [
      ['--udp', 'a', '--camera-url', 'http://a', '--camera-token', 'a/b'],
      /"--camera-token" must be 1\.\.128 of/,
    ],
  ])('refuses %j with a clear usage error', (argv, message) => {
    expect(usage(argv)).toMatch(message);
  });

  it('offers only the kinds a command takes', () => {
    expect(usage([], ['sim', 'udp', 'serial'])).toBe(
      'name the robot: one of --sim, --udp, --serial',
    );
    expect(usage(['--ws', 'ws://a'], ['sim', 'udp', 'serial'])).toMatch(/unknown option '--ws'/);
  });
});
