import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

/** The bare modules a file imports statically (`import type` and `await import()` excluded). */
function staticImports(file: URL): { local: URL[]; bare: string[] } {
  const source = readFileSync(file, 'utf8');
  const local: URL[] = [];
  const bare: string[] = [];
  const pattern = /^(?:import|export)\s+(?!type\b)[^;]*?from\s+'([^']+)';/gms;
  for (const match of source.matchAll(pattern)) {
    const specifier = match[1]!;
    if (specifier.startsWith('.')) local.push(new URL(specifier.replace(/\.js$/, '.ts'), file));
    else bare.push(specifier);
  }
  return { local, bare };
}

function reachable(entry: URL): { files: Set<string>; bare: string[] } {
  const files = new Set<string>();
  const bare = new Set<string>();
  const queue = [entry];
  while (queue.length > 0) {
    const file = queue.pop()!;
    if (files.has(file.href)) continue;
    files.add(file.href);
    const found = staticImports(file);
    queue.push(...found.local);
    for (const specifier of found.bare) bare.add(specifier);
  }
  return { files, bare: [...bare].sort() };
}

describe('@hal/remote in a browser bundle', () => {
  it('imports neither ws nor any Node built-in statically from its browser entry', () => {
    const { files, bare } = reachable(new URL('./index.ts', import.meta.url));
    expect(files.size).toBeGreaterThan(5);
    expect([...files].some((f) => f.includes('/server/'))).toBe(false);
    expect(bare).toEqual(['@hal/types', 'zod']);
  });

  it('keeps ws and the Node built-ins in the server entry', () => {
    const { bare } = reachable(new URL('./server/index.ts', import.meta.url));
    expect(bare).toEqual(expect.arrayContaining(['node:crypto', 'node:http', 'ws']));
  });
});
