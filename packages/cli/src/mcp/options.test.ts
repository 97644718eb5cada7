import { Command, CommanderError } from 'commander';
import { describe, expect, it } from 'vitest';
import { addMcpOptions, mcpOptions } from './options.js';
import type { McpCliOptions } from './options.js';
import { createRobot } from './robot.js';

/** Parses `argv` as `hal mcp` does; usage errors are thrown as CommanderErrors. */
function parseCli(argv: string[], env: Record<string, string | undefined>) {
  const command = addMcpOptions(new Command('mcp'))
    .exitOverride()
    .configureOutput({ writeErr: () => undefined, writeOut: () => undefined });
  return mcpOptions(command.parse(argv, { from: 'user' }).opts<McpCliOptions>(), env);
}

const quiet = { HAL_KEY: undefined, HAL_MCP_TOKEN: undefined };

describe('hal mcp options', () => {
  it('defaults to the simulator over stdio, HTTP on 127.0.0.1:3333 when asked', () => {
    expect(parseCli([], quiet)).toEqual({ http: false, host: '127.0.0.1', port: 3333, leash: {} });
    expect(parseCli(['--http', '--port', '0'], quiet)).toMatchObject({ http: true, port: 0 });
  });

  it('reads the robot, the key and the token from options or the environment', () => {
    expect(parseCli(['--udp', '10.0.0.5:4211', '--key', 'abcd'], quiet)).toMatchObject({
      udp: '10.0.0.5:4211',
      key: 'abcd',
    });
    expect(
      parseCli(['--serial', '/dev/ttyUSB0'], { HAL_KEY: '00ff', HAL_MCP_TOKEN: 't0k3n' }),
    ).toMatchObject({
      serial: '/dev/ttyUSB0',
      key: '00ff',
      token: 't0k3n',
    });
  });

  it('still refuses arguments that are not options', () => {
    expect(() => parseCli(['obstacles'], quiet)).toThrow(CommanderError);
  });

  it('turns leash options into a leash', () => {
    expect(
      parseCli(['--max-distance', '0.5', '--max-speed', '0.02', '--geofence', '-1,1,-2,2'], quiet)
        .leash,
    ).toEqual({
      maxDistanceM: 0.5,
      maxSpeedMPerS: 0.02,
      geofence: { minX: -1, maxX: 1, minY: -2, maxY: 2 },
    });
  });

  it('refuses bad options with a commander error', () => {
    for (const argv of [
      ['--port', 'x'],
      ['--geofence', '1,0,0,1'],
      ['--map', 'moon'],
      ['--bogus'],
    ]) {
      expect(() => parseCli(argv, quiet), argv.join(' ')).toThrow(CommanderError);
    }
  });
});

describe('createRobot', () => {
  it('builds a simulator with its map, or a PhysicalHAL for --udp and --serial', () => {
    const sim = createRobot({ map: 'obstacles' }, {});
    expect(sim.hal.mode).toBe('simulation');
    expect(sim.world.map?.()).toMatchObject({ name: 'obstacles' });
    const udp = createRobot({ udp: '127.0.0.1:4999' }, {});
    expect(udp.hal.mode).toBe('physical');
    expect(udp.world.map).toBeUndefined();
    expect(createRobot({ serial: '/dev/null' }, {}).hal.mode).toBe('physical');
    expect(() => createRobot({ udp: 'a:b:c' }, {})).toThrow(/host or host:port/);
    expect(() => createRobot({ udp: 'x', serial: 'y' }, {})).toThrow(/not both/);
  });
});
