// The public surface of the workspace packages: for each entry a package's package.json `exports`
// names, the names that entry exports and whether each is a value, a type or both, read with
// one TypeScript program over all the entries.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import ts from 'typescript';

/** What an exported name is to a user: something to call or read, a type, or both (a class). */
export type ExportKind = 'value' | 'type' | 'value, type';

/** Package name to entry (`.`, `./testing`, ...) to exported name to its kind, all sorted. */
export type PublicSurface = Record<string, Record<string, Record<string, ExportKind>>>;

/** Where the committed surface lives, relative to the repository. */
export const SURFACE_FILE = 'tests/structure/public-surface.json';

/** The command that rewrites {@link SURFACE_FILE}. */
export const SURFACE_COMMAND =
  'node --conditions=@hal/source --import tsx scripts/public-surface.ts';

interface PackageEntry {
  readonly packageName: string;
  readonly entry: string;
  readonly file: string;
}

/** Each package's entries, resolved through the `@hal/source` condition to their source files. */
function readEntries(repoRoot: string): PackageEntry[] {
  const entries: PackageEntry[] = [];
  const packagesDir = join(repoRoot, 'packages');
  for (const dir of readdirSync(packagesDir).sort()) {
    const manifestPath = join(packagesDir, dir, 'package.json');
    if (!existsSync(manifestPath)) continue;
    const manifest = JSON.parse(readFileSync(manifestPath, 'utf8')) as {
      name: string;
      exports?: Record<string, Record<string, string> | string>;
    };
    for (const [entry, target] of Object.entries(manifest.exports ?? {})) {
      const source = typeof target === 'string' ? target : target['@hal/source'];
      if (source === undefined || !source.endsWith('.ts')) continue;
      entries.push({
        packageName: manifest.name,
        entry,
        file: resolve(packagesDir, dir, source),
      });
    }
  }
  return entries;
}

function kindOf(checker: ts.TypeChecker, symbol: ts.Symbol): ExportKind {
  const target = symbol.flags & ts.SymbolFlags.Alias ? checker.getAliasedSymbol(symbol) : symbol;
  const isValue = (target.flags & ts.SymbolFlags.Value) !== 0;
  const isType = (target.flags & ts.SymbolFlags.Type) !== 0;
  // `export type { X }` re-exports only the type side, whatever X is
  const typeOnly = symbol.declarations?.some(
    (declaration) =>
      ts.isExportSpecifier(declaration) && ts.isTypeOnlyExportDeclaration(declaration),
  );
  if (isValue && !typeOnly) return isType ? 'value, type' : 'value';
  return 'type';
}

function sortedRecord<T>(entries: Iterable<[string, T]>): Record<string, T> {
  return Object.fromEntries([...entries].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0)));
}

/** Reads every package entry's exports from source. */
export function readPublicSurface(repoRoot: string): PublicSurface {
  const entries = readEntries(repoRoot);
  const configPath = join(repoRoot, 'tsconfig.json');
  const config = ts.getParsedCommandLineOfConfigFile(
    configPath,
    {},
    {
      ...ts.sys,
      onUnRecoverableConfigFileDiagnostic: (diagnostic) => {
        throw new Error(ts.flattenDiagnosticMessageText(diagnostic.messageText, '\n'));
      },
    },
  );
  if (config === undefined) throw new Error(`cannot read ${configPath}`);
  const program = ts.createProgram({
    rootNames: entries.map((entry) => entry.file),
    options: { ...config.options, noEmit: true },
  });
  const checker = program.getTypeChecker();

  const surface: Record<string, Record<string, Record<string, ExportKind>>> = {};
  for (const { packageName, entry, file } of entries) {
    const sourceFile = program.getSourceFile(file);
    if (sourceFile === undefined) throw new Error(`${packageName} "${entry}": no file ${file}`);
    const moduleSymbol = checker.getSymbolAtLocation(sourceFile);
    const exports = moduleSymbol === undefined ? [] : checker.getExportsOfModule(moduleSymbol);
    const names = sortedRecord(
      exports.map((symbol): [string, ExportKind] => [symbol.name, kindOf(checker, symbol)]),
    );
    surface[packageName] = { ...surface[packageName], [entry]: names };
  }
  return sortedRecord(
    Object.entries(surface).map(([name, byEntry]) => [name, sortedRecord(Object.entries(byEntry))]),
  );
}

/** The surface as the committed file spells it. */
export function formatSurface(surface: PublicSurface): string {
  return `${JSON.stringify(surface, null, 2)}\n`;
}

/** The names one surface has and the other lacks, as `@hal/x ./entry name (kind)` lines. */
export function surfaceChanges(
  committed: PublicSurface,
  current: PublicSurface,
): { added: string[]; removed: string[] } {
  const lines = (surface: PublicSurface): Set<string> =>
    new Set(
      Object.entries(surface).flatMap(([packageName, byEntry]) =>
        Object.entries(byEntry).flatMap(([entry, names]) =>
          Object.entries(names).map(([name, kind]) => `${packageName} ${entry} ${name} (${kind})`),
        ),
      ),
    );
  const before = lines(committed);
  const after = lines(current);
  return {
    added: [...after].filter((line) => !before.has(line)),
    removed: [...before].filter((line) => !after.has(line)),
  };
}
