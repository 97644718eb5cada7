// The build (`pnpm build`: `tsc -b tsconfig.build.json`) builds the packages in one process, in
// the order of their project references. A package that depends on another must reference it,
// or a fresh build may compile it before the dist/ it imports exists; and each build's
// .tsbuildinfo lives in its dist/, so deleting dist/ rebuilds it, and is kept out of the tarball.
import { readdirSync, readFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import { describe, expect, it } from 'vitest';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const packagesDir = join(repoRoot, 'packages');
const packageDirs = readdirSync(packagesDir).sort();

interface Manifest {
  name: string;
  files?: string[];
  dependencies?: Record<string, string>;
  peerDependencies?: Record<string, string>;
  optionalDependencies?: Record<string, string>;
}

interface BuildConfig {
  compilerOptions?: { composite?: boolean; tsBuildInfoFile?: string; outDir?: string };
  references?: Array<{ path: string }>;
}

const manifestOf = (dir: string): Manifest =>
  JSON.parse(readFileSync(join(packagesDir, dir, 'package.json'), 'utf8')) as Manifest;

/** A tsconfig file, read as tsc reads it (comments and trailing commas allowed). */
function readConfig(file: string): BuildConfig {
  const { config, error } = ts.readConfigFile(file, ts.sys.readFile);
  if (error !== undefined)
    throw new Error(ts.flattenDiagnosticMessageText(error.messageText, '\n'));
  return config as BuildConfig;
}

/** The package folders a config's references name. */
function referencedDirs(file: string): string[] {
  return (readConfig(file).references ?? [])
    .map((reference) => basename(dirname(resolve(dirname(file), reference.path))))
    .sort();
}

const dirOfName = new Map(packageDirs.map((dir) => [manifestOf(dir).name, dir]));

describe('the build of the packages', () => {
  it('lists every package in the root tsconfig.build.json', () => {
    expect(referencedDirs(join(repoRoot, 'tsconfig.build.json'))).toEqual(packageDirs);
  });

  it.each(packageDirs)('references exactly the workspace packages %s depends on', (dir) => {
    const manifest = manifestOf(dir);
    const depends = new Set<string>();
    for (const deps of [
      manifest.dependencies,
      manifest.peerDependencies,
      manifest.optionalDependencies,
    ]) {
      for (const [name, spec] of Object.entries(deps ?? {})) {
        const target = dirOfName.get(name);
        if (target !== undefined && spec.startsWith('workspace:')) depends.add(target);
      }
    }
    const file = join(packagesDir, dir, 'tsconfig.build.json');
    expect(referencedDirs(file)).toEqual([...depends].sort());
  });

  it.each(packageDirs)(
    'keeps the build information of %s in its dist/, out of its tarball',
    (dir) => {
      const options = readConfig(join(packagesDir, dir, 'tsconfig.build.json')).compilerOptions;
      expect(options?.composite).toBe(true);
      expect(options?.outDir).toBe('dist');
      expect(options?.tsBuildInfoFile).toMatch(/^dist\/[^/]+\.tsbuildinfo$/);
      expect(manifestOf(dir).files).toContain('!dist/*.tsbuildinfo');
    },
  );
});
