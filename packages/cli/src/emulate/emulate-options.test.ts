import { ROBOT_SETTINGS } from '@hal/types';
import { Command } from 'commander';
import { describe, expect, it } from 'vitest';
import { addEmulateOptions } from './emulate-options.js';

/** Parses `hal emulate`'s options from `args`; a refusal is returned as its message. */
function parse(args: string[]): Record<string, unknown> | string {
  const command = addEmulateOptions(new Command('emulate'))
    .exitOverride()
    .configureOutput({ writeErr: () => undefined, writeOut: () => undefined });
  try {
    command.parse(args, { from: 'user' });
    return command.opts();
  } catch (error) {
    return (error as Error).message;
  }
}

describe("hal emulate's options", () => {
  it("take --host-timeout-ms within the firmware's own range, from the settings table", () => {
    const host = ROBOT_SETTINGS.find((s) => s.key === 'hostTimeoutMs')!;
    expect(parse(['--host-timeout-ms', String(host.min)])).toMatchObject({
      hostTimeoutMs: host.min,
    });
    expect(parse(['--host-timeout-ms', String(host.max)])).toMatchObject({
      hostTimeoutMs: host.max,
    });
    expect(parse(['--host-timeout-ms', String(host.min - 1)])).toMatch(/--host-timeout-ms/);
    expect(parse(['--host-timeout-ms', String(host.max + 1)])).toMatch(/--host-timeout-ms/);
  });
});
