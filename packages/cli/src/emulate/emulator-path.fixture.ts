// The cube-emulator the tests run (built by `bash firmware/scripts/test.sh`, or in $CUBE_BUILD_DIR).
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { findFirmwareDir } from './locate-emulator.js';

export function builtEmulatorPath(): string {
  const firmware = findFirmwareDir();
  if (firmware === undefined) throw new Error('not inside the repository: no firmware/ folder');
  const path = join(process.env['CUBE_BUILD_DIR'] ?? join(firmware, 'build'), 'cube-emulator');
  if (!existsSync(path)) {
    throw new Error(
      `cube-emulator not found at ${path}: build it with "bash firmware/scripts/test.sh"`,
    );
  }
  return path;
}
