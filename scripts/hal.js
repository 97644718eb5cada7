#!/usr/bin/env node
// `hal` from a checkout (`pnpm hal ...`): runs packages/cli as one bundled file, which starts in a
// fraction of the time the sources take through tsx. The bundle is rebuilt (esbuild, about a
// second) when it is missing or when any file it was built from is newer than it; the list of
// those files is esbuild's own metafile, so the check is exact and costs a few stat calls.
// Packages with a native addon (serialport's bindings) or a WebAssembly file stay outside the
// bundle, loaded from the absolute place resolved at build time, so their prebuilt binaries (and
// .wasm files) load as they always do: an `import` takes it as a file:// URL, a CommonJS
// `require()` as a plain path (it refuses a URL).
import {
  existsSync,
  mkdirSync,
  readFileSync,
  readlinkSync,
  realpathSync,
  renameSync,
  statSync,
  symlinkSync,
  writeFileSync,
} from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import process from 'node:process';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
// one folder below the CLI's package.json, as its src/ and dist/ are (it reads ../package.json)
const outDir = join(root, 'packages', 'cli', '.bundle');
const outFile = join(outDir, 'hal.js');
const inputsFile = join(outDir, 'inputs.json');

function mtimeMs(path) {
  try {
    return statSync(path).mtimeMs;
  } catch {
    return undefined;
  }
}

/**
 * Why the bundle must be built (the first build, or the file that changed since the last one),
 * or undefined when it exists and no file it was built from has changed since.
 */
function staleness() {
  const built = mtimeMs(outFile);
  if (built === undefined) return 'the first build: there is no bundle yet';
  let inputs;
  try {
    inputs = JSON.parse(readFileSync(inputsFile, 'utf8'));
  } catch {
    return 'the list of files it was built from is missing';
  }
  for (const input of inputs) {
    const changed = mtimeMs(join(root, input));
    if (changed === undefined) return `${input} is gone since the last build`;
    if (changed > built) return `${input} changed since the last build`;
  }
  return undefined;
}

/**
 * True for a package with a native addon or a WebAssembly module, found by its manifest: it
 * loads files from beside its own, by path, so it stays outside the bundle.
 */
function isNative(resolvedFile) {
  for (let dir = dirname(resolvedFile); dir !== dirname(dir); dir = dirname(dir)) {
    let manifest;
    try {
      manifest = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
    } catch {
      continue;
    }
    if (manifest.name === undefined) continue; // a nested {"type": "module"} marker
    const deps = { ...manifest.dependencies, ...manifest.optionalDependencies };
    // a WebAssembly module (zstd for the recorder) is loaded from beside its script, by path
    const wasm = (manifest.files ?? []).some((file) => file.endsWith('.wasm'));
    return manifest.gypfile === true || wasm || NATIVE_LOADERS.some((name) => name in deps);
  }
  return false;
}
const NATIVE_LOADERS = ['node-gyp-build', 'node-addon-api', 'bindings', 'prebuild-install'];

/**
 * Links every third-party dependency of the bundled workspace packages into the bundle's own
 * node_modules, so that what a package imports at run time by a name no bundler can see (the
 * `ws` of @hal/remote, kept out of browser builds) resolves from the bundle as from the package.
 */
function linkDependencies(inputs) {
  // a link is only added or repointed, never removed first: a `hal` already running may be
  // resolving through them. The first package to name a dependency decides its version.
  const modules = join(outDir, 'node_modules');
  const packageDirs = new Set(inputs.map((p) => p.replace(/\/src\/.*$/, '')));
  const linked = new Set();
  for (const dir of packageDirs) {
    const manifest = JSON.parse(readFileSync(join(root, dir, 'package.json'), 'utf8'));
    const names = Object.keys({ ...manifest.dependencies, ...manifest.optionalDependencies });
    for (const name of names) {
      const installed = join(root, dir, 'node_modules', name);
      if (name.startsWith('@hal/') || linked.has(name) || !existsSync(installed)) continue;
      linked.add(name);
      const target = realpathSync(installed);
      const link = join(modules, name);
      let current;
      try {
        current = readlinkSync(link);
      } catch {
        current = undefined;
      }
      if (current === target) continue;
      mkdirSync(dirname(link), { recursive: true });
      // written aside and renamed over the old one (a dangling link after an upgrade)
      const partial = `${link}.${process.pid}.tmp`;
      symlinkSync(target, partial);
      renameSync(partial, link);
    }
  }
}

/** esbuild, or exit 1 saying how to install it: a clone before `pnpm install` has no node_modules. */
async function loadEsbuild() {
  try {
    return await import('esbuild');
  } catch (error) {
    if (error?.code !== 'ERR_MODULE_NOT_FOUND') throw error;
    process.stderr.write(
      'hal: FAILED: this checkout has no node_modules (esbuild is missing): run `bash scripts/setup.sh` (or `pnpm install`) first\n',
    );
    process.exit(1);
  }
}

async function build() {
  const esbuild = await loadEsbuild();
  const nativeOutside = {
    name: 'native-outside',
    setup(b) {
      b.onResolve({ filter: /^[^./]/ }, async (args) => {
        if (args.path.startsWith('node:') || args.pluginData === 'inner') return undefined;
        const found = await b.resolve(args.path, {
          kind: args.kind,
          resolveDir: args.resolveDir,
          importer: args.importer,
          pluginData: 'inner',
        });
        if (found.errors.length > 0 || !isNative(found.path)) return undefined;
        // require() takes a path and refuses a URL (serialport's CommonJS loads its bindings
        // so); an import takes the URL, which a Windows path with its drive letter is not
        const byPath = args.kind === 'require-call' || args.kind === 'require-resolve';
        return { path: byPath ? found.path : pathToFileURL(found.path).href, external: true };
      });
    },
  };
  const result = await esbuild.build({
    entryPoints: [join(root, 'packages', 'cli', 'src', 'main.ts')],
    outfile: outFile,
    absWorkingDir: root,
    write: false,
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    conditions: ['@hal/source'],
    plugins: [nativeOutside],
    // CommonJS dependencies inside an ES module bundle still call require()
    banner: {
      js: "import { createRequire as halCreateRequire } from 'node:module';\nconst require = halCreateRequire(import.meta.url);",
    },
    metafile: true,
    // smaller is faster: compiling the module is most of the start-up. Names are kept (errors and
    // classes read them), and the source map beside it makes a stack trace readable again
    // (node --enable-source-maps)
    minify: true,
    keepNames: true,
    sourcemap: 'linked',
    logLevel: 'error',
  });
  mkdirSync(outDir, { recursive: true });
  // written aside and renamed, so a second `hal` starting meanwhile never runs half a file
  // the map first: the bundle, renamed last, is what marks the build as done
  const last = (file) => Number(file.path === outFile);
  const outputs = [...result.outputFiles].sort((a, b) => last(a) - last(b));
  for (const output of outputs) {
    const partial = `${output.path}.${process.pid}.tmp`;
    writeFileSync(partial, output.contents);
    renameSync(partial, output.path);
  }
  const inputs = Object.keys(result.metafile.inputs).filter((p) => !p.includes('node_modules'));
  linkDependencies(inputs);
  // the manifests too: a changed dependency or export map can change what gets bundled
  const manifests = new Set(inputs.map((p) => p.replace(/\/src\/.*$/, '/package.json')));
  writeFileSync(
    `${inputsFile}.${process.pid}.tmp`,
    JSON.stringify([...inputs, ...manifests, 'scripts/hal.js']),
  );
  renameSync(`${inputsFile}.${process.pid}.tmp`, inputsFile);
}

const reason = staleness();
if (reason !== undefined) {
  process.stderr.write(`hal: bundling packages/cli (${reason})\n`);
  await build();
}
await import(pathToFileURL(outFile).href);
