// The packages under packages/, found when the test runs (a package added later is covered), and
// their tarballs as `pnpm pack` writes them.
import { execFile } from 'node:child_process';
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { promisify } from 'node:util';

const run = promisify(execFile);

/** The fields of a package.json this test reads. */
export interface Manifest {
  name: string;
  version: string;
  private?: boolean;
  license?: string;
  files?: string[];
  bin?: string | Record<string, string>;
  browser?: Record<string, string | false>;
  engines?: Record<string, string>;
  scripts?: Record<string, string>;
  exports?: Record<string, Record<string, string>>;
  publishConfig?: { access?: string; exports?: Record<string, Record<string, string>> };
  dependencies?: Record<string, string>;
  peerDependencies?: Record<string, string>;
  peerDependenciesMeta?: Record<string, { optional?: boolean }>;
}

export interface WorkspacePackage {
  /** The folder, e.g. `<repo>/packages/types`. */
  dir: string;
  manifest: Manifest;
}

export interface PackedPackage {
  name: string;
  version: string;
  /** Absolute path of the tarball. */
  filename: string;
}

export function readManifest(file: string): Manifest {
  return JSON.parse(readFileSync(file, 'utf8')) as Manifest;
}

/** Every folder under packages/ that has a package.json. */
export function workspacePackages(repoRoot: string): WorkspacePackage[] {
  const root = join(repoRoot, 'packages');
  return readdirSync(root)
    .map((name) => join(root, name))
    .filter((dir) => existsSync(join(dir, 'package.json')))
    .map((dir) => ({ dir, manifest: readManifest(join(dir, 'package.json')) }));
}

/** Newest modification time of the files under `dir` that pass `keep`, 0 when there are none. */
function newestMtime(dir: string, keep: (file: string) => boolean): number {
  if (!existsSync(dir)) return 0;
  let newest = 0;
  for (const entry of readdirSync(dir, { recursive: true, withFileTypes: true })) {
    if (!entry.isFile()) continue;
    const file = join(entry.parentPath, entry.name);
    if (keep(file)) newest = Math.max(newest, statSync(file).mtimeMs);
  }
  return newest;
}

/**
 * The packages whose dist/ is missing or older than their sources. `pnpm test` builds every
 * package before vitest runs, so this is empty there; a lone `vitest run` of this file builds
 * what is stale instead of packing an old dist.
 */
export function staleBuilds(packages: readonly WorkspacePackage[]): WorkspacePackage[] {
  return packages.filter(({ dir }) => {
    const built = newestMtime(join(dir, 'dist'), () => true);
    const source = newestMtime(join(dir, 'src'), (file) => !file.endsWith('.test.ts'));
    return built === 0 || source > built;
  });
}

export async function build(
  repoRoot: string,
  packages: readonly WorkspacePackage[],
): Promise<void> {
  for (const { manifest } of packages) {
    await run('pnpm', ['--filter', manifest.name, 'run', 'build'], { cwd: repoRoot });
  }
}

/**
 * Packs every package into `destination` with one `pnpm pack` (workspace: and catalog:
 * specifiers rewritten, publishConfig applied). Lifecycle scripts are skipped: `prepack` would
 * rebuild each package, which `pnpm test` has just done.
 */
export async function packAll(repoRoot: string, destination: string): Promise<PackedPackage[]> {
  const { stdout } = await run(
    'pnpm',
    [
      '-r',
      '--filter',
      './packages/*',
      '--config.ignore-scripts=true',
      'pack',
      '--pack-destination',
      destination,
      '--json',
    ],
    { cwd: repoRoot, maxBuffer: 64 * 1024 * 1024 },
  );
  const parsed = JSON.parse(stdout) as PackedPackage | PackedPackage[];
  return (Array.isArray(parsed) ? parsed : [parsed]).map(({ name, version, filename }) => ({
    name,
    version,
    filename,
  }));
}
