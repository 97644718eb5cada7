import { Command } from 'commander';
import { describe, expect, it } from 'vitest';
import { CliError } from '../cli-error.js';
import { addFoxgloveOptions, foxglovePlan } from './live-view.js';
import type { FoxgloveCliOptions } from './live-view.js';

function parse(args: string[]): FoxgloveCliOptions {
  const command = addFoxgloveOptions(new Command().exitOverride()).allowExcessArguments(false);
  command.parse(args, { from: 'user' });
  return command.opts<FoxgloveCliOptions>();
}

describe('--foxglove', () => {
  it('takes Foxglove port 8765 when given no port, and any port given', () => {
    expect(foxglovePlan(parse(['--foxglove']), {})).toEqual({ host: '127.0.0.1', port: 8765 });
    expect(foxglovePlan(parse(['--foxglove', '0']), {})).toMatchObject({ port: 0 });
    expect(foxglovePlan(parse([]), {})).toBeUndefined();
  });

  it('reads the token from $HAL_FOXGLOVE_TOKEN, and lets a non-loopback host serve with one', () => {
    const token = 'a-long-enough-token';
    expect(
      foxglovePlan(parse(['--foxglove', '--foxglove-host', '0.0.0.0']), {
        HAL_FOXGLOVE_TOKEN: token,
      }),
    ).toMatchObject({ host: '0.0.0.0', token });
  });

  it('refuses a non-loopback host without a token, naming --foxglove-token', () => {
    expect(() => foxglovePlan(parse(['--foxglove', '--foxglove-host', '0.0.0.0']), {})).toThrow(
      /--foxglove-token/,
    );
  });

  it('refuses the --foxglove-* options without --foxglove, and an origin that is none', () => {
    expect(() => foxglovePlan(parse(['--foxglove-camera-rate', '5']), {})).toThrow(CliError);
    expect(() => parse(['--foxglove', '--foxglove-allow-origin', 'app.foxglove.dev'])).toThrow(
      /origin/,
    );
    expect(
      foxglovePlan(
        parse(['--foxglove', '--foxglove-allow-origin', 'https://app.foxglove.dev']),
        {},
      ),
    ).toMatchObject({ allowedOrigins: ['https://app.foxglove.dev'] });
  });
});
