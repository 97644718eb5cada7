// Where the firmware's cube-emulator is built inside a checkout: the one rule `hal emulate`, the
// tests and the benchmarks share. $CUBE_BUILD_DIR names the build directory (as for
// firmware/scripts/test.sh), else it is firmware/build. Light on purpose (no CLI code), so tests
// import it as `@hal/cli/emulator`.
import { existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The program's file name in its build directory. */
export const EMULATOR_NAME = 'cube-emulator';

type Env = Readonly<Record<string, string | undefined>>;

/** The repository's firmware folder, when this package runs from a checkout. */
export function findFirmwareDir(
  start = dirname(fileURLToPath(import.meta.url)),
): string | undefined {
  for (let dir = start; ; dir = dirname(dir)) {
    if (existsSync(join(dir, 'firmware', 'CMakeLists.txt'))) return join(dir, 'firmware');
    if (dirname(dir) === dir) return undefined;
  }
}

/** The firmware host build directory: $CUBE_BUILD_DIR, else `firmware/build` of `firmware`. */
export function emulatorBuildDir(env: Env, firmware: string): string {
  const named = env['CUBE_BUILD_DIR'];
  return named !== undefined && named !== '' ? named : join(firmware, 'build');
}

/**
 * The cube-emulator of the checkout's build (which may not be built yet): in $CUBE_BUILD_DIR when
 * that is set, else in the firmware folder's `build`. Throws outside a checkout with neither.
 */
export function builtEmulatorPath(env: Env = process.env): string {
  const named = env['CUBE_BUILD_DIR'];
  if (named !== undefined && named !== '') return join(named, EMULATOR_NAME);
  const firmware = findFirmwareDir();
  if (firmware === undefined) {
    throw new Error('cube-emulator: not inside the repository (no firmware/ folder)');
  }
  return join(emulatorBuildDir(env, firmware), EMULATOR_NAME);
}
