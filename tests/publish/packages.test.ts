// The packages as a user gets them from npm. Packs every package under packages/ (found at run
// time) with `pnpm pack`, installs the tarballs with npm into a temporary app outside the
// workspace (both once for the run, shared with installs.test.ts: shared.ts), runs a plain `node`
// ESM program there that imports each package by name and drives SimulationHAL, runs the
// installed `hal` against the firmware emulator over UDP, serial, WebSocket and NATS, and bundles
// the library packages for the browser with vite.
//
// Needs: pnpm and npm on PATH, tar, and the npm registry or a warm npm cache for the third-party
// dependencies (zod, crc, serialport, jpeg-js, three): npm installs them with --prefer-offline;
// the cube-emulator (firmware/scripts/test.sh builds it) and nats-server.
// Packs the dist/ that `pnpm test` builds just before (a stale or missing dist is rebuilt first).
// Everything it writes is in the run's temporary folder (published.global.ts), removed at the end.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { TRANSPORTS, expectFromRobot, statusOver } from '../cli/every-transport.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import { bundleForBrowser, isNativePackage, packageDirOf } from './browser-bundle.js';
import { everythingAppOnce, packedOnce } from './shared.js';
import { cleanEnv, packedFiles, packedManifest, runAppCommand, runNodeApp } from './temp-app.js';
import type { Manifest, PackedPackage, WorkspacePackage } from './workspace-packages.js';
import { workspacePackages } from './workspace-packages.js';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));

/** A workspace package beside its tarball and the manifest inside the tarball. */
interface Published {
  source: WorkspacePackage;
  packed: PackedPackage;
  manifest: Manifest;
  /** The paths inside the tarball, without the leading `package/`. */
  files: string[];
}

/** Whether an export entry resolves only for Node (a `node` condition, no `import`). */
function entryNodeOnly(entry: unknown): boolean {
  return (
    typeof entry === 'object' &&
    entry !== null &&
    'node' in entry &&
    !('import' in entry) &&
    !('default' in entry) &&
    !('browser' in entry)
  );
}

/** Whether every entry of a package resolves only for Node. */
function nodeOnly(manifest: { exports?: Record<string, unknown> }): boolean {
  const entries = Object.values(manifest.exports ?? {});
  return entries.length > 0 && entries.every(entryNodeOnly);
}

describe('the packages as published', () => {
  let appDir: string;
  let published: Published[];

  beforeAll(async () => {
    // A package marked private is not published (none is today).
    const sources = workspacePackages(repoRoot).filter((p) => p.manifest.private !== true);
    const packed = await packedOnce(repoRoot);
    published = await Promise.all(
      sources.map(async (source) => {
        const tarball = packed.find((p) => p.name === source.manifest.name);
        if (!tarball) throw new Error(`pnpm pack wrote no tarball for ${source.manifest.name}`);
        const [manifest, files] = await Promise.all([
          packedManifest(tarball.filename),
          packedFiles(tarball.filename),
        ]);
        return { source, packed: tarball, manifest, files };
      }),
    );
    // every tarball and three (for the scene binding), as a user installs them
    appDir = await everythingAppOnce(repoRoot, packed);
  }, 300_000);

  it('packs every package under packages/ with its metadata, dist and license, and no workspace specifier', () => {
    expect(published.length).toBeGreaterThanOrEqual(6);
    for (const { source, manifest, files } of published) {
      const name = manifest.name;
      // What the repository declares: public, a build before packing, the Node it needs.
      expect(source.manifest.publishConfig?.access, name).toBe('public');
      expect(source.manifest.scripts?.['prepack'], name).toMatch(/\bbuild\b/);
      expect(source.manifest.engines?.['node'], name).toBe('>=20.19');
      expect(manifest.license, name).toBe('MIT');
      expect(files, name).toEqual(expect.arrayContaining(['LICENSE', 'README.md']));
      // Dependencies carry real versions: no workspace: or catalog: reaches a user.
      for (const [dependency, range] of Object.entries(manifest.dependencies ?? {})) {
        expect(range, `${name} -> ${dependency}`).not.toMatch(/^(workspace|catalog):/);
      }
      // Every export points into dist/, never at the sources, and the files are in the tarball.
      expect(JSON.stringify(manifest.exports ?? {}), name).not.toContain('@hal/source');
      for (const [subpath, conditions] of Object.entries(manifest.exports ?? {})) {
        for (const target of Object.values(conditions)) {
          expect(target, `${name} ${subpath}`).toMatch(/^\.\/dist\//);
          expect(files, `${name} ${subpath}`).toContain(target.slice(2));
        }
      }
      // No tests or fixtures, except src/readme.test.ts: pnpm's packlist always includes a file
      // named readme.* in any folder. It only runs the README's examples and nothing imports it.
      const testFiles = files.filter(
        (file) => /\.(test|fixture)\.ts$/.test(file) && !/(^|\/)readme\.[^/]*$/i.test(file),
      );
      expect(testFiles, name).toEqual([]);
    }
  });

  it("installs the packages' one command, hal (with hal mcp and hal serve), which runs from the app", async () => {
    const bins = published.flatMap(({ manifest }) =>
      typeof manifest.bin === 'string'
        ? [manifest.name.replace(/^@[^/]+\//, '')]
        : Object.keys(manifest.bin ?? {}),
    );
    expect(bins).toEqual(['hal']);
    for (const args of [['--help'], ['mcp', '--help'], ['serve', '--help']]) {
      const { stdout, stderr } = await runAppCommand(appDir, 'hal', args);
      expect(stdout + stderr, args.join(' ')).toMatch(/Usage: hal/);
    }
    const status = await runAppCommand(appDir, 'hal', ['--json', 'status', '--sim']);
    expect(JSON.parse(status.stdout.split('\n')[0]!)).toMatchObject({
      device: { mode: 'simulation' },
    });
  });

  it("answers hal status with the emulated robot's own identity over UDP, serial, WebSocket and NATS", async () => {
    const hal = {
      command: join(appDir, 'node_modules', '.bin', 'hal'),
      args: [],
      cwd: appDir,
      env: cleanEnv(),
    };
    const deviceId = 'cube-packed';
    const [emulator, nats] = await Promise.all([startEmulator({ deviceId }), startNatsServer()]);
    try {
      for (const way of TRANSPORTS) {
        expectFromRobot(await statusOver(way, hal, { emulator, nats }), deviceId);
      }
    } finally {
      await Promise.all([stopAllEmulators(), stopAllNatsServers()]);
    }
  }, 180_000);

  it('imports each package by name from its dist in plain Node and drives SimulationHAL 10 cm forward', async () => {
    const names = published.map((p) => p.manifest.name);
    const report = await runNodeApp(appDir, names);

    for (const { manifest } of published) {
      const main = report.imports.find((entry) => entry.specifier === manifest.name);
      expect(main?.error, manifest.name).toBeUndefined();
      expect(main?.exportCount, manifest.name).toBeGreaterThan(0);
    }
    for (const entry of report.imports) {
      if (entry.error === undefined) {
        const [scope, base] = entry.specifier.split('/');
        expect(entry.resolved).toContain(`/node_modules/${scope}/${base}/dist/`);
        continue;
      }
      // A subpath may need an optional peer this app did not install (vitest for @hal/types/testing).
      const owner = published.find((p) => entry.specifier.startsWith(`${p.manifest.name}/`));
      const optional = Object.keys(owner?.manifest.peerDependenciesMeta ?? {});
      expect(entry.code, entry.error).toBe('ERR_MODULE_NOT_FOUND');
      expect(
        optional.some((peer) => entry.error?.includes(`'${peer}'`)),
        `${entry.specifier}: ${entry.error}`,
      ).toBe(true);
    }

    expect(report.moved.success).toBe(true);
    const dx = report.after.position.x - report.before.position.x;
    const dy = report.after.position.y - report.before.position.y;
    expect(Math.hypot(dx, dy)).toBeCloseTo(0.1, 3);
    expect(report.after.rotation.yaw).toBeCloseTo(report.before.rotation.yaw, 6);
    expect(report.framePrefix).toBe('data:image/jpeg;base64,');
  }, 120_000);

  it('bundles the library packages for a browser with no Node built-in and no native module in it', async () => {
    // Packages that ship a command are Node programs, and so are those whose entries resolve only
    // under the `node` export condition (@hal/nats: its NATS transport is Node's); every other
    // package is a library a browser may import. A subpath beyond the main entry is bundled when
    // the package's peers are installed.
    const libraries = published.filter(
      (p) => p.manifest.bin === undefined && !nodeOnly(p.manifest),
    );
    const specifiers = libraries.flatMap(({ manifest }) => {
      const peers = Object.keys(manifest.peerDependencies ?? {});
      const peersInstalled = peers.every((peer) =>
        existsSync(join(appDir, 'node_modules', peer, 'package.json')),
      );
      // a Node-only subpath (@hal/fleet/node, the device manager) is not for browsers
      return Object.entries(manifest.exports ?? {})
        .filter(([subpath, entry]) => (subpath === '.' || peersInstalled) && !entryNodeOnly(entry))
        .map(([subpath]) => subpath)
        .map((subpath) =>
          subpath === '.' ? manifest.name : `${manifest.name}/${subpath.slice(2)}`,
        );
    });
    expect(specifiers).toEqual(expect.arrayContaining(['@hal/simulation/three', '@hal/physical']));

    const bundle = await bundleForBrowser(appDir, specifiers);

    // The bundle really holds every library (and three, for the scene binding).
    const packagesInBundle = new Set(bundle.modules.map((id) => packageDirOf(id)));
    for (const { manifest } of libraries) {
      expect(packagesInBundle, manifest.name).toContain(
        join(appDir, 'node_modules', manifest.name),
      );
    }
    expect(packagesInBundle).toContain(join(appDir, 'node_modules', 'three'));

    // Nothing native: serialport and its bindings stay out (mapped away by @hal/physical's
    // "browser" field).
    const native = [...packagesInBundle].filter(
      (dir): dir is string => dir !== undefined && isNativePackage(dir),
    );
    expect(native).toEqual([]);

    // Node-only imports become vite's empty stub; none may be static (it would be needed when the
    // page loads); the ones left are loaded with import() by functions that only work in Node.
    const staticNodeImports = bundle.externals.filter((external) => external.importers.length > 0);
    expect(staticNodeImports).toEqual([]);
    for (const external of bundle.externals) {
      expect(external.dynamicImporters.length, external.id).toBeGreaterThan(0);
    }
    expect(bundle.externals.map((external) => external.id)).toContain('serialport');
  }, 180_000);
});
