// Which tarballs each package needs: the @hal packages it depends on, directly or through another,
// as package.json says, and as the table in docs/cli.md ("From packed tarballs") tells a user.
import type { WorkspacePackage } from './workspace-packages.js';

/** The first header cell of the table in docs/cli.md. */
export const TARBALL_TABLE_HEADER = 'to use';

/** Each package's name with the other @hal packages it needs, sorted. */
export function halDependencyClosure(packages: readonly WorkspacePackage[]): Map<string, string[]> {
  const direct = new Map(
    packages.map(({ manifest }) => [
      manifest.name,
      Object.keys(manifest.dependencies ?? {}).filter((name) => name.startsWith('@hal/')),
    ]),
  );
  const closure = new Map<string, string[]>();
  for (const name of direct.keys()) {
    const found = new Set<string>();
    const visit = (from: string) => {
      for (const next of direct.get(from) ?? []) {
        if (found.has(next)) continue;
        found.add(next);
        visit(next);
      }
    };
    visit(name);
    closure.set(name, [...found].sort());
  }
  return closure;
}

/** The `@hal/...` names written as code (in backticks) in a table cell. */
function namesIn(cell: string): string[] {
  return [...cell.matchAll(/`(@hal\/[a-z0-9-]+)`/g)].map((match) => match[1]!);
}

/**
 * The table of `markdown` whose header's first cell is `header`: each row's first cell's package
 * with the packages its second cell names, sorted. Rows whose first cell names no package are
 * skipped; an empty map when there is no such table.
 */
export function tarballTable(markdown: string, header: string): Map<string, string[]> {
  const lines = markdown.split('\n');
  const start = lines.findIndex((line) => line.startsWith(`| ${header} |`));
  const rows = new Map<string, string[]>();
  if (start < 0) return rows;
  for (const line of lines.slice(start + 2)) {
    if (!line.startsWith('|')) break;
    const [first = '', second = ''] = line.split('|').slice(1);
    const [name] = namesIn(first);
    if (name !== undefined) rows.set(name, namesIn(second).sort());
  }
  return rows;
}
