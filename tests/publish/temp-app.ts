// A temporary app outside the workspace, as a user would make one: its own package.json, the
// packed tarballs and their third-party dependencies installed by npm.
import { execFile } from 'node:child_process';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { promisify } from 'node:util';
import type { Manifest, PackedPackage } from './workspace-packages.js';

const run = promisify(execFile);

/** The environment for child processes, without what pnpm and vitest put into it. */
export function cleanEnv(): NodeJS.ProcessEnv {
  const env: NodeJS.ProcessEnv = {};
  for (const [key, value] of Object.entries(process.env)) {
    const fromPnpm =
      /^pnpm_/i.test(key) ||
      /^npm_(command|execpath|node_execpath|lifecycle_|package_)/i.test(key) ||
      /^npm_config_(user_agent|verify_deps_before_run)$/i.test(key);
    if (!fromPnpm && key !== 'NODE_OPTIONS' && !key.startsWith('VITEST')) env[key] = value;
  }
  return env;
}

/** The manifest inside a tarball, as a registry would serve it. */
export async function packedManifest(tarball: string): Promise<Manifest> {
  const { stdout } = await run('tar', ['-xzOf', tarball, 'package/package.json']);
  return JSON.parse(stdout) as Manifest;
}

/** The paths inside a tarball, without the leading `package/`. */
export async function packedFiles(tarball: string): Promise<string[]> {
  const { stdout } = await run('tar', ['-tzf', tarball], { maxBuffer: 16 * 1024 * 1024 });
  return stdout
    .split('\n')
    .filter((line) => line.startsWith('package/') && !line.endsWith('/'))
    .map((line) => line.slice('package/'.length));
}

/**
 * Installs the tarballs into `appDir`. Each @hal package is also an override (unless `overrides`
 * is false), so that a package depending on another (`"@hal/types": "0.1.0"` after packing) gets
 * the local tarball, never a registry lookup; without overrides the app is installed as the docs
 * tell a user to: the tarballs given together, each @hal dependency found among them. `extra` are
 * further dependencies a user's app adds (three for the scene). Install scripts are skipped:
 * serialport's bindings load the prebuilt binary their package ships (the installed `hal` opens
 * the emulator's pty with it), and build nothing.
 */
export async function installApp(
  appDir: string,
  packed: readonly PackedPackage[],
  extra: Record<string, string>,
  { overrides = true }: { overrides?: boolean } = {},
): Promise<void> {
  const local = Object.fromEntries(packed.map((p) => [p.name, `file:${p.filename}`]));
  const manifest = {
    name: 'hal-published-packages-app',
    private: true,
    type: 'module',
    dependencies: { ...local, ...extra },
    ...(overrides ? { overrides: local } : {}),
  };
  writeFileSync(join(appDir, 'package.json'), `${JSON.stringify(manifest, null, 2)}\n`);
  await run(
    'npm',
    [
      'install',
      '--no-audit',
      '--no-fund',
      '--prefer-offline',
      '--ignore-scripts',
      '--loglevel=error',
    ],
    { cwd: appDir, env: cleanEnv(), timeout: 240_000, maxBuffer: 16 * 1024 * 1024 },
  );
}

export interface ImportReport {
  specifier: string;
  resolved?: string;
  exportCount?: number;
  code?: string;
  error?: string;
}

interface PoseReport {
  position: { x: number; y: number; z: number };
  rotation: { yaw: number; pitch: number; roll: number };
}

export interface NodeAppReport {
  imports: ImportReport[];
  before: PoseReport;
  after: PoseReport;
  moved: { success: boolean; code?: string };
  framePrefix: string;
}

/** Runs tests/publish/node-app.mjs with plain `node` in the app, importing `names`. */
export async function runNodeApp(appDir: string, names: readonly string[]): Promise<NodeAppReport> {
  copyFileSync(new URL('./node-app.mjs', import.meta.url), join(appDir, 'node-app.mjs'));
  const { stdout } = await run(process.execPath, ['node-app.mjs', JSON.stringify(names)], {
    cwd: appDir,
    env: cleanEnv(),
    timeout: 60_000,
  });
  return JSON.parse(stdout) as NodeAppReport;
}

/** Runs a command the app's packages installed (node_modules/.bin/NAME) in the app. */
export async function runAppCommand(
  appDir: string,
  name: string,
  args: readonly string[],
  timeoutMs = 60_000,
): Promise<{ stdout: string; stderr: string }> {
  return run(join(appDir, 'node_modules', '.bin', name), [...args], {
    cwd: appDir,
    env: cleanEnv(),
    timeout: timeoutMs,
  });
}

/**
 * The version of `name` the workspace has installed (from `from`'s node_modules), as a caret
 * range: what a user's app adds beside the packages (typescript, vitest, three's types).
 */
export function workspaceVersion(repoRoot: string, name: string, from = '.'): string {
  const manifest = join(repoRoot, from, 'node_modules', name, 'package.json');
  return `^${(JSON.parse(readFileSync(manifest, 'utf8')) as { version: string }).version}`;
}
