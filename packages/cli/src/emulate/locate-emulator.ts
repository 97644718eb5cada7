// Finds the cube-emulator program for `hal emulate`: the one named by --emulator or
// $CUBE_EMULATOR, else, inside the repository, the firmware host build, configured and built
// (only the cube-emulator target: an up-to-date binary costs a no-op), as bench/ensure-emulator.ts
// does for the benchmarks.
import { spawn } from 'node:child_process';
import { accessSync, constants, existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { CliError } from '../cli-error.js';
import { EMULATOR_NAME, emulatorBuildDir, findFirmwareDir } from './emulator-build.js';

export interface LocateOptions {
  /** --emulator PATH. */
  explicit?: string;
  env: Readonly<Record<string, string | undefined>>;
  signal: AbortSignal;
  /** Told before a build starts (it can take minutes the first time). */
  onBuild?: (buildDir: string) => void;
}

function checkExecutable(path: string, from: string): string {
  try {
    accessSync(path, constants.X_OK);
  } catch {
    throw new CliError('NOT_FOUND', `${from}: ${path} is not an executable cube-emulator`);
  }
  return path;
}

function run(command: string, args: string[], signal: AbortSignal): Promise<void> {
  return new Promise((done, fail) => {
    const child = spawn(command, args, { stdio: ['ignore', 'pipe', 'pipe'], signal });
    let output = '';
    child.stdout.on('data', (chunk: Buffer) => (output += chunk.toString()));
    child.stderr.on('data', (chunk: Buffer) => (output += chunk.toString()));
    child.once('error', (error) =>
      fail(new CliError('FAILED', `cannot run ${command}: ${error.message}`)),
    );
    child.once('exit', (code) => {
      if (code === 0) done();
      else
        fail(
          new CliError(
            'FAILED',
            `building cube-emulator failed (${command} ${args.join(' ')}):\n${output.trim()}`,
          ),
        );
    });
  });
}

/** The cube-emulator to run; builds it from the checkout's firmware when needed. */
export async function locateEmulator(options: LocateOptions): Promise<string> {
  if (options.explicit !== undefined)
    return checkExecutable(resolve(options.explicit), '--emulator');
  const fromEnv = options.env['CUBE_EMULATOR'];
  if (fromEnv !== undefined && fromEnv !== '') return checkExecutable(fromEnv, '$CUBE_EMULATOR');
  const firmware = findFirmwareDir();
  if (firmware === undefined) {
    throw new CliError(
      'NOT_FOUND',
      'cube-emulator not found: pass --emulator PATH or set $CUBE_EMULATOR (it is built from the ' +
        "repository's firmware/ with cmake, see docs/firmware.md)",
    );
  }
  const buildDir = emulatorBuildDir(options.env, firmware);
  options.onBuild?.(buildDir);
  if (!existsSync(join(buildDir, 'CMakeCache.txt'))) {
    await run(
      'cmake',
      ['-S', firmware, '-B', buildDir, '-G', 'Ninja', '-DCMAKE_BUILD_TYPE=RelWithDebInfo'],
      options.signal,
    );
  }
  const jobs = options.env['CUBE_JOBS'] ?? '2';
  await run('cmake', ['--build', buildDir, '--target', EMULATOR_NAME, '-j', jobs], options.signal);
  return checkExecutable(join(buildDir, EMULATOR_NAME), 'the build');
}
