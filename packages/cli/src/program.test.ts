import { Command } from 'commander';
import { HalError } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { captureIO } from './testing/capture-io.js';
import { CliError } from './cli-error.js';
import { emit } from './io.js';
import { buildProgram, runHal, runProgram } from './program.js';

/** Runs `hal` with one extra command, `probe`, whose action is `action`. */
async function runProbe(action: (json: boolean) => void | Promise<void>, argv: string[]) {
  const io = captureIO();
  const program = buildProgram(io);
  program.addCommand(
    new Command('probe')
      .exitOverride()
      .action(() => action(program.opts<{ json: boolean }>().json)),
  );
  const code = await runProgram(program, argv, io);
  return { io, code };
}

describe('hal', () => {
  it('prints its version and help, and exits 0', async () => {
    const io = captureIO();
    expect(await runHal(['--version'], io)).toBe(0);
    expect(io.stdout()).toMatch(/^\d+\.\d+\.\d+\n$/);
    const help = captureIO();
    expect(await runHal(['--help'], help)).toBe(0);
    expect(help.stdout()).toContain('Usage: hal');
    expect(help.stdout()).toContain('--json');
  });

  it('refuses an unknown command as a usage error, --help or not, naming it', async () => {
    for (const argv of [
      ['nosuch'],
      ['nosuch', '--help'],
      ['--json', 'nosuch', '-h'],
      ['help', 'nosuch'],
    ]) {
      const io = captureIO();
      expect(await runHal(argv, io), argv.join(' ')).toBe(2);
      expect(io.stdout(), argv.join(' ')).not.toContain('Usage: hal');
      expect(io.stderr(), argv.join(' ')).toMatch(
        /hal: USAGE: unknown command 'nosuch'|"message":"unknown command 'nosuch'"/,
      );
    }
    // a known command's help is still help
    const help = captureIO();
    expect(await runHal(['drive', '--help'], help)).toBe(0);
    expect(help.stdout()).toContain('Usage: hal drive');
  });

  it('refuses an unknown option with exit code 2', async () => {
    const bad = captureIO();
    expect(await runHal(['--no-such-option'], bad)).toBe(2);
    // in the one-line form of every failure, not commander's own "error: ..."
    expect(bad.stderr()).toMatch(/^hal: USAGE: unknown option '--no-such-option'$/m);
    expect(bad.stderr()).not.toMatch(/^error: /m);
  });

  it('exits 2 on a bad option of any subcommand, nested ones too, without ending the process', async () => {
    const nested = (cmd: Command): Command | undefined =>
      cmd.commands.find((c) => c.commands.length > 0);
    const parent = nested(buildProgram(captureIO()));
    expect(parent).toBeDefined();
    const child = parent!.commands[0]!;
    const io = captureIO();
    expect(await runHal([parent!.name(), child.name(), '--no-such-option'], io)).toBe(2);
    expect(io.stderr()).toMatch(/^hal: USAGE: unknown option '--no-such-option'$/m);
  });

  it('reports a usage error as a JSON error document with --json', async () => {
    const io = captureIO();
    expect(await runHal(['--json', '--no-such-option'], io)).toBe(2);
    const last = io.stderr().trim().split('\n').at(-1)!;
    expect(JSON.parse(last)).toMatchObject({ error: { code: 'USAGE' } });
  });

  it('writes a command failure as CODE: message and exits 1, HAL codes unchanged', async () => {
    const hal = await runProbe(() => {
      throw new HalError('NOT_CONNECTED', 'device cube-07 is offline');
    }, ['probe']);
    expect(hal.code).toBe(1);
    expect(hal.io.stderr()).toBe('hal: NOT_CONNECTED: device cube-07 is offline\n');
    const cli = await runProbe(() => {
      throw new CliError('USAGE', 'give --device or --all');
    }, ['probe']);
    expect(cli.code).toBe(2);
    expect(cli.io.stderr()).toBe('hal: USAGE: give --device or --all\n');
  });

  it('writes a command failure as a JSON document with --json', async () => {
    const { io, code } = await runProbe(() => {
      throw new HalError('RANGE_EXCEEDED', 'too fast', { details: { limit: 1 } });
    }, ['--json', 'probe']);
    expect(code).toBe(1);
    expect(JSON.parse(io.stderr())).toEqual({
      error: { code: 'RANGE_EXCEEDED', message: 'too fast', details: { limit: 1 } },
    });
  });

  it('emits results as human text, or one JSON line each with --json', async () => {
    const action = (json: boolean) => {
      const io = captureIO();
      emit(io, { json }, { device: 'cube-01', online: true }, () => 'cube-01 online');
      return io.stdout();
    };
    expect(action(false)).toBe('cube-01 online\n');
    expect(JSON.parse(action(true))).toEqual({ device: 'cube-01', online: true });
  });
});
