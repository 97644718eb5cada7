// The shell blocks of a markdown file: every fenced block whose language is sh, bash, shell or
// console, with the `<!-- not run: REASON -->` marker of the line right before its fence. A line
// scanner rather than a markdown parser: fences are the one construct needed, and a marker must
// be on the exact line before the fence, which a parser's tree does not keep.
import { fences } from './fences.js';

export const SHELL_LANGUAGES = ['sh', 'bash', 'shell', 'console'] as const;

/** One shell block of a document. */
export interface ShellBlock {
  /** The document, relative to the repository root, e.g. `docs/cli.md`. */
  file: string;
  /** The 1-based line of the opening fence. */
  line: number;
  language: (typeof SHELL_LANGUAGES)[number];
  /** The block's text, as written (indentation of a fence inside a list removed). */
  text: string;
  /** The reason of a `<!-- not run: REASON -->` marker, when the block has one. */
  notRun?: string;
}

/** A marker that is not on the line before a shell fence, or says no reason. */
export interface MisplacedMarker {
  file: string;
  line: number;
  text: string;
}

const MARKER = /^\s*<!--\s*not run:\s*(.*?)\s*-->\s*$/;
// a comment line that looks like a marker (prose that quotes one in backticks is not)
const ANY_MARKER = /^\s*<!--\s*not run\b/i;

/** Every shell block of `markdown`, and every marker that belongs to none (or gives no reason). */
export function shellBlocks(
  markdown: string,
  file: string,
): { blocks: ShellBlock[]; misplaced: MisplacedMarker[] } {
  const lines = markdown.split('\n');
  const blocks: ShellBlock[] = [];
  const misplaced: MisplacedMarker[] = [];
  const usedMarkers = new Set<number>();
  const fenced = new Set<number>(); // lines inside any fenced block, whose text is an example
  for (const { open: i, end, indent, info } of fences(lines)) {
    for (let j = i + 1; j < end; j += 1) fenced.add(j);
    const language = SHELL_LANGUAGES.find((l) => l === info.toLowerCase());
    if (language !== undefined) {
      const body = lines
        .slice(i + 1, end)
        .map((l) => (l.startsWith(indent) ? l.slice(indent.length) : l));
      const marker = i > 0 ? MARKER.exec(lines[i - 1]!) : null;
      const reason = marker?.[1];
      if (marker !== null && reason !== undefined && reason !== '') usedMarkers.add(i - 1);
      blocks.push({
        file,
        line: i + 1,
        language,
        text: body.join('\n'),
        ...(reason === undefined || reason === '' ? {} : { notRun: reason }),
      });
    }
  }
  lines.forEach((text, index) => {
    if (ANY_MARKER.test(text) && !usedMarkers.has(index) && !fenced.has(index)) {
      misplaced.push({ file, line: index + 1, text: text.trim() });
    }
  });
  return { blocks, misplaced };
}

/**
 * The commands of a block as a script: lines joined where they end in a backslash; for a console
 * block, only the lines after a `$ ` prompt (the others are the output shown).
 */
export function commandLines(block: Pick<ShellBlock, 'language' | 'text'>): string[] {
  const raw = block.text.split('\n');
  const lines =
    block.language === 'console'
      ? raw.filter((l) => /^\s*\$ /.test(l)).map((l) => l.replace(/^\s*\$ /, ''))
      : raw;
  const commands: string[] = [];
  let pending = '';
  for (const line of lines) {
    if (line.endsWith('\\')) {
      pending += `${line}\n`;
      continue;
    }
    commands.push(pending + line);
    pending = '';
  }
  if (pending !== '') commands.push(pending.replace(/\\\n$/, ''));
  return commands.filter((c) => c.trim() !== '' && !c.trim().startsWith('#'));
}
