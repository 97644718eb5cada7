// The cube-emulator the tests run (built by `bash firmware/scripts/test.sh`, or in $CUBE_BUILD_DIR).
import { existsSync } from 'node:fs';
import { builtEmulatorPath as buildPath } from './emulator-build.js';

/** The built cube-emulator; throws, saying how to build it, when there is none. */
export function builtEmulatorPath(): string {
  const path = buildPath();
  if (!existsSync(path)) {
    throw new Error(
      `cube-emulator not found at ${path}: build it with "bash firmware/scripts/test.sh"`,
    );
  }
  return path;
}
