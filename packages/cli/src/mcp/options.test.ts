import { Command, CommanderError } from 'commander';
import { describe, expect, it } from 'vitest';
import { addMcpOptions, mcpOptions } from './options.js';
import type { McpCliOptions } from './options.js';

/** Parses `argv` as `hal mcp` does; commander's own usage errors are thrown as CommanderErrors. */
function parseCli(argv: string[], env: Record<string, string | undefined> = {}) {
  const command = addMcpOptions(new Command('mcp'))
    .exitOverride()
    .configureOutput({ writeErr: () => undefined, writeOut: () => undefined });
  return mcpOptions(command.parse(argv, { from: 'user' }).opts<McpCliOptions>(), env);
}

const usage = expect.objectContaining({ name: 'CliError', code: 'USAGE', exitCode: 2 });

describe('hal mcp options', () => {
  it('defaults to the simulator over stdio with the HAL tools, HTTP on 127.0.0.1:3333 when asked', () => {
    expect(parseCli([])).toEqual({
      target: { kind: 'sim', map: 'empty', speed: 1 },
      profile: 'primitives',
      http: false,
      host: '127.0.0.1',
      port: 3333,
      leash: {},
      approve: 'none',
      approvalTimeoutMs: 30_000,
      overwrite: false,
    });
    expect(parseCli(['--http', '--port', '0'])).toMatchObject({ http: true, port: 0 });
  });

  it('takes who approves motions: motion, over:DISTANCE, none (over HTTP too); refuses the rest', () => {
    expect(parseCli(['--approve', 'motion'])).toMatchObject({ approve: 'motion' });
    expect(parseCli(['--approve', 'over:30cm'])).toMatchObject({ approve: { overM: 0.3 } });
    expect(parseCli(['--approve', 'over:0.5'])).toMatchObject({ approve: { overM: 0.5 } });
    expect(parseCli(['--approve', 'none', '--http'])).toMatchObject({ approve: 'none' });
    expect(parseCli(['--approve', 'motion', '--approval-timeout', '5000'])).toMatchObject({
      approvalTimeoutMs: 5000,
    });
    for (const bad of ['always', 'over:', 'over:far', 'over:-1m']) {
      expect(() => parseCli(['--approve', bad])).toThrow(
        /"--approve" must be motion, none or over:DISTANCE/,
      );
    }
    expect(parseCli(['--approve', 'motion', '--http'])).toMatchObject({
      approve: 'motion',
      http: true,
    });
    expect(() => parseCli(['--approval-timeout', '10'])).toThrow(/--approval-timeout/);
  });

  it("takes its robot from the target options every command has, $HAL_KEY the key's default", () => {
    expect(parseCli(['--udp', '[::1]:4211', '--key', 'abcd']).target).toEqual({
      kind: 'udp',
      host: '::1',
      port: 4211,
      key: 'abcd',
      timeScale: 1,
    });
    expect(parseCli(['--serial', '/dev/ttyUSB0'], { HAL_KEY: '00ff' }).target).toMatchObject({
      kind: 'serial',
      path: '/dev/ttyUSB0',
      key: '00ff',
    });
    expect(parseCli(['--ws', 'ws://127.0.0.1:8765', '--token', 'a'.repeat(16)]).target).toEqual({
      kind: 'ws',
      url: 'ws://127.0.0.1:8765',
      token: 'a'.repeat(16),
    });
    expect(
      parseCli(['--device', 'cube-01', '--nats', 'nats://127.0.0.1:4333']).target,
    ).toMatchObject({ kind: 'nats', deviceId: 'cube-01' });
    expect(
      parseCli([
        '--sim',
        '--map',
        'obstacles',
        '--calibration',
        'cal.json',
        '--connect-timeout',
        '500',
      ]),
    ).toMatchObject({
      target: { kind: 'sim', map: 'obstacles', calibration: 'cal.json' },
      connectTimeoutMs: 500,
    });
  });

  it('offers the tools of the profile --tools names, and starts the simulator in a --world', () => {
    expect(parseCli(['--tools', 'skills']).profile).toBe('skills');
    expect(parseCli(['--tools', 'all']).profile).toBe('all');
    expect(parseCli(['--tools', 'primitives']).profile).toBe('primitives');
    expect(parseCli(['--world', 'w.json'])).toMatchObject({
      target: { kind: 'sim' },
      world: 'w.json',
    });
    expect(parseCli(['--sim', '--world', 'w.json']).world).toBe('w.json');
  });

  it('reads the HTTP token from --http-token or $HAL_MCP_TOKEN', () => {
    expect(parseCli(['--http-token', 't'.repeat(16)]).token).toBe('t'.repeat(16));
    expect(parseCli([], { HAL_MCP_TOKEN: 'e'.repeat(16) }).token).toBe('e'.repeat(16));
  });

  it('turns leash options into a leash, distances with their unit', () => {
    expect(
      parseCli(['--max-distance', '50cm', '--max-speed', '0.02', '--geofence', '-1,1,-200cm,2m'])
        .leash,
    ).toEqual({
      maxDistanceM: 0.5,
      maxSpeedMPerS: 0.02,
      geofence: { minX: -1, maxX: 1, minY: -2, maxY: 2 },
    });
  });

  it('refuses bad values with the one usage error, naming the option', () => {
    for (const [argv, message] of [
      [['--port', '99999'], '"--port" must be an integer in 0..65535, got "99999"'],
      [['--port', 'x'], '"--port" must be an integer in 0..65535, got "x"'],
      [['--udp', 'a:b:c'], /"--udp" must be HOST, HOST:PORT or \[IPV6\]:PORT/],
      [
        ['--udp', 'x', '--serial', 'y'],
        'name one robot, not --udp and --serial (one of --sim, --udp, --serial, --ws, --device)',
      ],
      [['--key', 'abc', '--udp', 'x'], /"--key" must be 1..64 bytes/],
      [['--geofence', '1,0,0,1'], /"--geofence" is minX,maxX,minY,maxY/],
      [['--max-distance', 'far'], /"--max-distance" must be a distance/],
      [['--timeout', '5'], '"--timeout" must be an integer in 100..600000, got "5"'],
      [
        ['--tools', 'move_forward'],
        '"--tools" must be one of skills, primitives, all, got "move_forward"',
      ],
      [['--tools', ''], '"--tools" must be one of skills, primitives, all, got ""'],
      [['--world', 'w.json', '--udp', 'x'], '"--world" needs the simulator (--sim)'],
      [
        ['--world', 'w.json', '--map', 'maze'],
        '"--world" and "--map" both name the world: give one',
      ],
      [
        ['--http', '--host', '0.0.0.0'],
        /"--host" 0.0.0.0 is reachable from other machines: give --http-token/,
      ],
    ] as const) {
      expect(() => parseCli([...argv]), argv.join(' ')).toThrow(
        expect.objectContaining({
          name: 'CliError',
          code: 'USAGE',
          message: typeof message === 'string' ? message : expect.stringMatching(message),
        }),
      );
    }
    expect(() => parseCli(['--http', '--host', '0.0.0.0', '--http-token', 'short'])).toThrow(usage);
    expect(parseCli(['--http', '--host', '0.0.0.0', '--http-token', 's'.repeat(16)]).host).toBe(
      '0.0.0.0',
    );
  });

  it('leaves unknown options and stray words to commander', () => {
    expect(() => parseCli(['obstacles'])).toThrow(CommanderError);
    expect(() => parseCli(['--bogus'])).toThrow(CommanderError);
    expect(() => parseCli(['--map', 'moon'])).toThrow(CommanderError);
  });
});
