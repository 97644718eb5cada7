// Builds cube-emulator for the benchmarks that start it, so `pnpm bench` works straight after
// scripts/setup.sh. It checks the system tools first (firmware/scripts/require.sh: a missing one
// is named with its Debian package), configures the firmware build like firmware/scripts/test.sh
// when the build directory has none, then builds only the cube-emulator target: Ninja is
// incremental, so a missing or stale binary is rebuilt and an up-to-date one costs a no-op.
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { errorMessage } from '@hal/types';
import { EMULATOR_PATH } from '../tests/physical/emulator.js';

const firmwareDir = fileURLToPath(new URL('../firmware', import.meta.url));
const requireScript = join(firmwareDir, 'scripts/require.sh');

export interface EnsureEmulatorOptions {
  /** The build directory; default the one tests/physical/emulator.ts runs from ($CUBE_BUILD_DIR). */
  buildDir?: string;
  /** The environment of the checks and the build (PATH, CXX); default this process's. */
  env?: NodeJS.ProcessEnv;
}

/** Runs a step; throws its output, under `what` when given, else under the command line. */
function run(command: string, args: readonly string[], env: NodeJS.ProcessEnv, what?: string) {
  const result = spawnSync(command, args, { env, encoding: 'utf8', timeout: 15 * 60_000 });
  if (result.error !== undefined) {
    throw new Error(`cube-emulator build: cannot run ${command}: ${result.error.message}`);
  }
  if (result.status !== 0) {
    const output = `${result.stdout}${result.stderr}`.trim();
    const step = what ?? `cube-emulator build: ${command} ${args.join(' ')} failed`;
    throw new Error(step === '' ? output : `${step}\n${output}`);
  }
}

/** Builds cube-emulator when it is missing or stale; returns its path. Throws with the reason. */
export function ensureEmulator(options: EnsureEmulatorOptions = {}): string {
  const env = options.env ?? process.env;
  const buildDir = options.buildDir ?? dirname(EMULATOR_PATH);
  run(
    'sh',
    ['-c', '. "$1" && require_host_build && require_end "pnpm bench"', 'sh', requireScript],
    env,
    '', // require.sh's report says it all
  );
  if (!existsSync(join(buildDir, 'CMakeCache.txt'))) {
    run(
      'cmake',
      ['-S', firmwareDir, '-B', buildDir, '-G', 'Ninja', '-DCMAKE_BUILD_TYPE=RelWithDebInfo'],
      env,
    );
  }
  const jobs = env['CUBE_JOBS'] ?? '2';
  run('cmake', ['--build', buildDir, '--target', 'cube-emulator', '-j', jobs], env);
  return join(buildDir, 'cube-emulator');
}

/** The benchmarks among `files` (in `dir`) that start the emulator. */
export function benchmarksUsingEmulator(dir: string, files: readonly string[]): string[] {
  return files.filter((file) => readFileSync(join(dir, file), 'utf8').includes('startEmulator('));
}

/** For bench/run.ts: builds the emulator if a selected benchmark needs it, or exits with why not. */
export function ensureEmulatorFor(dir: string, files: readonly string[]): void {
  if (benchmarksUsingEmulator(dir, files).length === 0) return;
  if (!existsSync(EMULATOR_PATH)) console.error(`building ${EMULATOR_PATH} (once)...`);
  try {
    ensureEmulator();
  } catch (error) {
    console.error(errorMessage(error));
    process.exit(1);
  }
}
