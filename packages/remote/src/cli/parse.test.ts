import { CommanderError } from 'commander';
import { describe, expect, it } from 'vitest';
import { parseServeCommand, serveProgram } from './parse.js';

function parse(...argv: string[]) {
  const program = serveProgram()
    .exitOverride()
    .configureOutput({ writeErr: () => undefined, writeOut: () => undefined });
  return parseServeCommand(argv, program);
}

function refusal(...argv: string[]): string {
  try {
    parse(...argv);
  } catch (e) {
    if (e instanceof CommanderError) return e.message;
    throw e;
  }
  throw new Error('parsed without error');
}

describe('hal-serve command line', () => {
  it('serves the simulator on 127.0.0.1:8765 by default', () => {
    expect(parse()).toMatchObject({
      hal: { kind: 'sim' },
      host: '127.0.0.1',
      port: 8765,
      heartbeatTimeoutMs: 2000,
    });
  });

  it('reads a UDP robot with its default port, a key and a token', () => {
    const token = 'sixteen-chars-token';
    expect(parse('--udp', '192.168.4.1', '--key', 'a1b2', '--token', token)).toMatchObject({
      hal: { kind: 'udp', host: '192.168.4.1', port: 4210, key: 'a1b2' },
      token,
    });
    expect(parse('--udp', '127.0.0.1:5000').hal).toMatchObject({ port: 5000 });
  });

  it('reads a serial robot with a baud rate', () => {
    expect(parse('--serial', '/dev/ttyUSB0', '--baud', '115200').hal).toEqual({
      kind: 'serial',
      path: '/dev/ttyUSB0',
      baudRate: 115200,
    });
  });

  it.each([
    [['--udp', 'host:99999'], /"--udp" must be HOST or HOST:PORT/],
    [['--udp', 'a', '--serial', '/dev/x'], /cannot be used with/],
    [['--sim', '--udp', 'a'], /cannot be used with/],
    [['--key', 'zz', '--udp', 'a'], /"--key" must be hex/],
    [['--key', 'a1b2'], /"--key" needs --udp or --serial/],
    [['--port', '-1'], /"--port" must be an integer 0..65535/],
    [['--heartbeat-timeout', '50'], /"--heartbeat-timeout" must be an integer 100..10000/],
    [['--bogus'], /unknown option '--bogus'/],
  ])('refuses %j with a clear error', (argv, message) => {
    expect(refusal(...argv)).toMatch(message);
  });
});
