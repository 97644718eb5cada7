// Bundles a browser entry with vite, as a user's app would, and reports what the bundle's module
// graph holds: which modules, and which Node-only imports vite replaced by its empty browser stub,
// statically or behind a dynamic import().
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { isBuiltin } from 'node:module';
import { join } from 'node:path';
import { build } from 'vite';
import type { Plugin, Rollup } from 'vite';

/** An import a browser cannot run: a Node built-in, or a package mapped away by a `browser` field. */
export interface BrowserExternal {
  /** The specifier, e.g. `node:dgram` or `serialport`. */
  id: string;
  /** Modules that import it statically: these would need it the moment the page loads. */
  importers: string[];
  /** Modules that load it with `import()`: only when a Node-only function is called. */
  dynamicImporters: string[];
}

export interface BrowserBundleReport {
  /** Every module in an output chunk (absolute file paths and virtual ids). */
  modules: string[];
  externals: BrowserExternal[];
  /** Warnings vite and rollup logged. */
  warnings: string[];
}

const STUB_PREFIX = '\0browser-external:';

/**
 * Names vite's browser stub: where vite would resolve an import to its anonymous empty module
 * (`__vite-browser-external`, for Node built-ins and `browser`-field `false` entries), this plugin
 * gives the same empty module a name, so the module graph tells which import it stands for.
 * Everything else resolves exactly as vite resolves it.
 */
function nameBrowserExternals(found: BrowserExternal[]): Plugin {
  return {
    name: 'name-browser-externals',
    enforce: 'pre',
    async resolveId(source, importer, options) {
      if (source.startsWith(STUB_PREFIX)) return source;
      const resolved = await this.resolve(source, importer, { ...options, skipSelf: true });
      if (resolved?.id.startsWith('__vite-browser-external') || (!resolved && isBuiltin(source))) {
        return `${STUB_PREFIX}${source}`;
      }
      return resolved;
    },
    load(id) {
      return id.startsWith(STUB_PREFIX) ? 'export default {};' : null;
    },
    generateBundle() {
      for (const id of this.getModuleIds()) {
        if (!id.startsWith(STUB_PREFIX)) continue;
        const info = this.getModuleInfo(id);
        found.push({
          id: id.slice(STUB_PREFIX.length),
          importers: [...(info?.importers ?? [])],
          dynamicImporters: [...(info?.dynamicImporters ?? [])],
        });
      }
    },
  };
}

/**
 * Builds `specifiers` (each imported as a namespace and kept alive on globalThis, so nothing is
 * tree-shaken away) for the browser, in memory.
 */
export async function bundleForBrowser(
  appDir: string,
  specifiers: readonly string[],
): Promise<BrowserBundleReport> {
  const entry = join(appDir, 'browser-entry.js');
  writeFileSync(
    entry,
    [
      ...specifiers.map((specifier, i) => `import * as m${i} from '${specifier}';`),
      `globalThis.halPackages = [${specifiers.map((_, i) => `m${i}`).join(', ')}];`,
      '',
    ].join('\n'),
  );
  const warnings: string[] = [];
  const externals: BrowserExternal[] = [];
  const output = await build({
    root: appDir,
    configFile: false,
    mode: 'production',
    plugins: [nameBrowserExternals(externals)],
    customLogger: {
      info: () => undefined,
      warn: (message) => warnings.push(message),
      warnOnce: (message) => warnings.push(message),
      error: (message) => warnings.push(message),
      clearScreen: () => undefined,
      hasErrorLogged: () => false,
      hasWarned: false,
    },
    build: {
      write: false,
      target: 'es2022',
      minify: false,
      reportCompressedSize: false,
      chunkSizeWarningLimit: 10_000,
      rollupOptions: { input: entry },
    },
  });
  const results = (Array.isArray(output) ? output : [output]) as Rollup.RollupOutput[];
  const modules = results.flatMap((result) =>
    result.output.flatMap((item) => (item.type === 'chunk' ? item.moduleIds : [])),
  );
  return { modules, externals, warnings };
}

const NATIVE_LOADERS = ['node-gyp-build', 'bindings', 'prebuild-install', 'node-addon-api'];

/**
 * The package folder a module file lives in; undefined for a module outside node_modules and for
 * a virtual module (`\0` ids: helpers and proxies of the file modules, which are listed too).
 */
export function packageDirOf(file: string): string | undefined {
  if (file.startsWith('\0')) return undefined;
  const marker = '/node_modules/';
  const at = file.lastIndexOf(marker);
  if (at < 0) return undefined;
  const rest = file.slice(at + marker.length).split('/');
  const depth = rest[0]?.startsWith('@') ? 2 : 1;
  return file.slice(0, at + marker.length) + rest.slice(0, depth).join('/');
}

/** True for a package that ships or builds a native addon (or loads one: serialport does). */
export function isNativePackage(dir: string): boolean {
  if (existsSync(join(dir, 'binding.gyp')) || existsSync(join(dir, 'prebuilds'))) return true;
  const manifest = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8')) as {
    name?: string;
    gypfile?: boolean;
    dependencies?: Record<string, string>;
  };
  if (manifest.gypfile === true) return true;
  if (manifest.name === 'serialport' || manifest.name?.startsWith('@serialport/')) return true;
  return NATIVE_LOADERS.some((loader) => manifest.dependencies?.[loader] !== undefined);
}
