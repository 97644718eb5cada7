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

describe('@hal/simulation in a browser bundle', () => {
  it('imports nothing Node-only or native statically, and names sharp to no bundler', () => {
    const seen = new Set<string>();
    const bare = new Set<string>();
    const queue = [new URL('./index.ts', import.meta.url)];
    while (queue.length > 0) {
      const file = queue.pop()!;
      if (seen.has(file.href)) continue;
      seen.add(file.href);
      const found = staticImports(file);
      queue.push(...found.local);
      for (const specifier of found.bare) bare.add(specifier);
    }
    expect(seen.size).toBeGreaterThan(20);
    expect([...bare].sort()).toEqual(['@hal/kinematics', '@hal/types', 'zod']);
    // sharp is loaded only through a variable specifier, which bundlers leave alone.
    for (const href of seen) {
      expect(readFileSync(new URL(href), 'utf8'), href).not.toMatch(/import\(\s*['"]sharp['"]/);
    }
  });
});
