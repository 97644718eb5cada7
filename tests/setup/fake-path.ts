// A PATH for a child process that has every command this one's PATH has, except the ones named:
// how the tests show what a machine without a package sees, without uninstalling anything.
import { existsSync, mkdtempSync, readdirSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { delimiter, join } from 'node:path';

export interface FakePath {
  /** The PATH value: one directory of symlinks. */
  path: string;
  remove(): void;
}

export function pathWithout(commands: readonly string[]): FakePath {
  const dir = mkdtempSync(join(tmpdir(), 'fake-path-'));
  const linked = new Set<string>();
  for (const source of (process.env['PATH'] ?? '').split(delimiter)) {
    if (source === '' || !existsSync(source)) continue;
    for (const name of readdirSync(source)) {
      if (commands.includes(name) || linked.has(name)) continue;
      symlinkSync(join(source, name), join(dir, name));
      linked.add(name);
    }
  }
  return { path: dir, remove: () => rmSync(dir, { recursive: true, force: true }) };
}
