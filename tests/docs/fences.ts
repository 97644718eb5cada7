// The fenced code blocks of a markdown file, found by a line scanner (what the shell blocks and
// the links tests both need to tell an example from prose).

/** One fenced block. */
export interface Fence {
  /** Index (0-based) of the opening fence's line. */
  open: number;
  /** Index of the closing fence's line (the line count for a block never closed). */
  end: number;
  /** The opening fence's indentation (a fence inside a list). */
  indent: string;
  /** The info string's first word: the block's language, as written. */
  info: string;
}

const FENCE = /^(\s*)(`{3,}|~{3,})\s*([\w-]*)/;

/** Every fenced block of `lines`, in order. */
export function fences(lines: readonly string[]): Fence[] {
  const found: Fence[] = [];
  for (let i = 0; i < lines.length; i += 1) {
    const open = FENCE.exec(lines[i]!);
    if (open === null) continue;
    const [, indent = '', fence = '', info = ''] = open;
    let end = i + 1;
    while (end < lines.length && !isClosing(lines[end]!, fence)) end += 1;
    found.push({ open: i, end, indent, info });
    i = end;
  }
  return found;
}

function isClosing(line: string, fence: string): boolean {
  const trimmed = line.trim();
  return trimmed.startsWith(fence[0]!.repeat(fence.length)) && /^[`~]+$/.test(trimmed);
}
