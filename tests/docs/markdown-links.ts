// The relative links of a Markdown file, and the anchors its headings make, as GitHub renders
// them: what the links test checks every doc against.
import GithubSlugger from 'github-slugger';
import { fences } from './fences.js';

/** A link written in a Markdown file. */
export interface MarkdownLink {
  /** 1-based line of the link. */
  line: number;
  /** The path part (empty for a link within the file). */
  path: string;
  /** The anchor, without `#` (undefined for none). */
  anchor: string | undefined;
}

const LINK = /!?\[(?:[^\]]|\][^(])*?\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)/g;
const INLINE_CODE = /`[^`]*`/g;

/** Each line of `markdown` outside fenced code blocks, with its 1-based number. */
function proseLines(markdown: string): { line: number; text: string }[] {
  const lines = markdown.split('\n');
  const fenced = new Set<number>();
  for (const { open, end } of fences(lines)) for (let i = open; i <= end; i += 1) fenced.add(i);
  return lines.flatMap((text, i) => (fenced.has(i) ? [] : [{ line: i + 1, text }]));
}

/** The links of `markdown` to files of the repository (not to web addresses or mail). */
export function relativeLinks(markdown: string): MarkdownLink[] {
  const links: MarkdownLink[] = [];
  for (const { line, text } of proseLines(markdown)) {
    for (const match of text.replace(INLINE_CODE, '').matchAll(LINK)) {
      const target = match[1] ?? '';
      if (/^[a-z][a-z0-9+.-]*:/i.test(target)) continue; // https:, mailto:
      const hash = target.indexOf('#');
      links.push({
        line,
        path: decodeURI(hash < 0 ? target : target.slice(0, hash)),
        anchor: hash < 0 ? undefined : target.slice(hash + 1),
      });
    }
  }
  return links;
}

/** The anchors `markdown` has: its headings' GitHub slugs, and explicit `id`/`name` attributes. */
export function anchorsOf(markdown: string): Set<string> {
  const slugger = new GithubSlugger();
  const anchors = new Set<string>();
  for (const { text } of proseLines(markdown)) {
    const heading = /^#{1,6}\s+(.*?)\s*#*\s*$/.exec(text)?.[1];
    if (heading !== undefined) {
      // GitHub slugs the heading's text as shown: a link's text, code without its backticks
      const shown = heading.replace(/\[([^\]]*)\]\([^)]*\)/g, '$1').replace(/[*_]{1,2}(\S)/g, '$1');
      anchors.add(slugger.slug(shown));
    }
    for (const id of text.matchAll(/<a\s+(?:id|name)="([^"]+)"/g)) anchors.add(id[1] ?? '');
  }
  return anchors;
}
