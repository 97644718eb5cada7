import { Command } from 'commander';
import { describe, expect, it } from 'vitest';
import { addNatsOptions, deviceIdArg, natsConnectOptions } from './nats-options.js';
import type { NatsCliOptions } from './nats-options.js';

function parse(argv: string[]): NatsCliOptions {
  const command = addNatsOptions(new Command('x').exitOverride());
  command.parse(argv, { from: 'user' });
  return command.opts<NatsCliOptions>();
}

describe('NATS options', () => {
  it('defaults to the local server, then $NATS_URL and the credentials in the environment', () => {
    expect(natsConnectOptions(parse([]), {})).toEqual({
      servers: ['nats://127.0.0.1:4222'],
      name: 'hal-cli',
    });
    expect(
      natsConnectOptions(parse([]), {
        NATS_URL: 'nats://a:4222, nats://b:4222',
        NATS_USER: 'ops',
        NATS_PASS: 'secret',
      }),
    ).toEqual({
      servers: ['nats://a:4222', 'nats://b:4222'],
      user: 'ops',
      pass: 'secret',
      name: 'hal-cli',
    });
  });

  it('prefers the options to the environment and passes TLS files through', () => {
    const options = parse([
      '--nats',
      'tls://hub:4443',
      '--nats-token',
      't0k',
      '--nats-ca',
      'ca.pem',
    ]);
    expect(natsConnectOptions(options, { NATS_URL: 'nats://ignored', NATS_TOKEN: 'env' })).toEqual({
      servers: ['tls://hub:4443'],
      token: 't0k',
      tls: { caFile: 'ca.pem' },
      name: 'hal-cli',
    });
  });

  it('takes a device id only if it is one subject token', () => {
    expect(deviceIdArg('cube-01')).toBe('cube-01');
    for (const bad of ['', 'a.b', 'cube 1', '*', '>', 'x'.repeat(65)]) {
      expect(() => deviceIdArg(bad)).toThrow(
        expect.objectContaining({ name: 'CliError', code: 'USAGE' }),
      );
    }
  });
});
