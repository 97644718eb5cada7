// What the README and docs/architecture.md say about the packages: the dependency drawing (a
// fenced block of `name -> dep dep` lines, top to bottom), and the tables that list the packages.

/** The lines of a markdown file's section, from its `## heading` to the next `## ` heading. */
export function section(markdown: string, heading: string): string[] {
  const lines = markdown.split('\n');
  const start = lines.findIndex((line) => line.trim() === `## ${heading}`);
  if (start < 0) throw new Error(`no "## ${heading}" section`);
  const end = lines.findIndex((line, i) => i > start && line.startsWith('## '));
  return lines.slice(start + 1, end < 0 ? lines.length : end);
}

/** A drawing line: a package, its arrows, an optional note in parentheses. */
const ARROW_LINE = /^([a-z][a-z0-9-]*)\s*(?:->\s*([a-z0-9 -]*?))?\s*(?:\([^)]*\))?$/;

/**
 * The arrows of the first fenced block of a section: `cli -> fleet remote` reads as
 * `@hal/cli` depends on `@hal/fleet` and `@hal/remote`. Throws on a line it cannot read, so
 * a drawing changed into another form fails the test instead of passing it empty.
 */
export function drawnArrows(lines: readonly string[]): Map<string, Set<string>> {
  const open = lines.findIndex((line) => line.startsWith('```'));
  const close = lines.findIndex((line, i) => i > open && line.startsWith('```'));
  if (open < 0 || close < 0) throw new Error('no fenced dependency drawing in the section');
  const arrows = new Map<string, Set<string>>();
  for (const line of lines.slice(open + 1, close)) {
    if (line.trim() === '') continue;
    const match = ARROW_LINE.exec(line.trim());
    if (match === null) throw new Error(`unreadable drawing line: ${JSON.stringify(line)}`);
    const deps = (match[2] ?? '').split(/\s+/).filter((dep) => dep !== '');
    arrows.set(`@hal/${match[1]!}`, new Set(deps.map((dep) => `@hal/${dep}`)));
  }
  return arrows;
}

/** The rows of the section's table whose header is `header`, as cells. */
export function tableRows(lines: readonly string[], header: readonly string[]): string[][] {
  const cells = (line: string) =>
    line
      .trim()
      .replace(/^\||\|$/g, '')
      .split('|')
      .map((cell) => cell.trim());
  const start = lines.findIndex(
    (line) => line.startsWith('|') && cells(line).join('|') === header.join('|'),
  );
  if (start < 0) throw new Error(`no table with the columns ${header.join(', ')}`);
  const rows: string[][] = [];
  for (const line of lines.slice(start + 2)) {
    if (!line.startsWith('|')) break;
    rows.push(cells(line));
  }
  return rows;
}

/** The `@hal/*` package names a piece of markdown mentions, in order. */
export function packageNames(text: string): string[] {
  return [...text.matchAll(/@hal\/[a-z0-9-]+/g)].map((match) => match[0]);
}
