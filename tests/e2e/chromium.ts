// Where the browser tests find Chromium: $CHROMIUM_PATH, else Debian's /usr/bin/chromium. A
// missing browser fails with the Debian package to install, as the firmware scripts do.
import { existsSync } from 'node:fs';
import { packageOfCommand } from '../setup/system-tools.js';

export const DEFAULT_CHROMIUM_PATH = '/usr/bin/chromium';

/**
 * The flags every browser test starts Chromium with: headless, without a GPU (WebGL is drawn in
 * software, by SwiftShader, as on a CI machine or a server), and nothing of its own on the
 * network. A root user's container needs `--no-sandbox`.
 */
export const CHROMIUM_FLAGS: readonly string[] = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
];

/** The browser the tests launch: `$CHROMIUM_PATH` when set, else Debian's chromium. */
export function chromiumPath(env: NodeJS.ProcessEnv = process.env): string {
  return env['CHROMIUM_PATH'] ?? DEFAULT_CHROMIUM_PATH;
}

/** Returns the browser's path, or throws an error that names the Debian package. */
export function requireChromium(env: NodeJS.ProcessEnv = process.env): string {
  const path = chromiumPath(env);
  if (!existsSync(path)) {
    const pkg = packageOfCommand('chromium');
    throw new Error(
      `no Chromium at ${path}: install the Debian package ${pkg} ("sudo apt-get install -y ${pkg}"; bash scripts/setup.sh installs everything the project needs), or set CHROMIUM_PATH`,
    );
  }
  return path;
}
