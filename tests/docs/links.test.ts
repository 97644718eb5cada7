import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { anchorsOf, relativeLinks } from './markdown-links.js';

const root = join(import.meta.dirname, '..', '..');
const markdownFiles = execFileSync('git', ['ls-files', '*.md'], { cwd: root, encoding: 'utf8' })
  .split('\n')
  .filter((f) => f !== '');

describe('the links of the docs', () => {
  it("reads the repository's Markdown files and finds links in them (the scan works at all)", () => {
    expect(markdownFiles).toContain('README.md');
    expect(markdownFiles.some((f) => f.startsWith('docs/'))).toBe(true);
    expect(relativeLinks(readFileSync(join(root, 'README.md'), 'utf8')).length).toBeGreaterThan(5);
  });

  it('lead to files that exist, and to headings those files have', () => {
    const broken: string[] = [];
    const anchors = new Map<string, Set<string>>();
    const anchorsIn = (file: string): Set<string> => {
      let found = anchors.get(file);
      if (found === undefined) {
        found = anchorsOf(readFileSync(file, 'utf8'));
        anchors.set(file, found);
      }
      return found;
    };
    for (const doc of markdownFiles) {
      const from = join(root, doc);
      for (const link of relativeLinks(readFileSync(from, 'utf8'))) {
        const target = link.path === '' ? from : join(dirname(from), link.path);
        const where = `${doc}:${link.line} -> ${link.path}${link.anchor !== undefined ? `#${link.anchor}` : ''}`;
        if (!existsSync(target)) {
          broken.push(`${where}: no such file (${relative(root, target)})`);
          continue;
        }
        if (
          link.anchor !== undefined &&
          link.anchor !== '' &&
          statSync(target).isFile() &&
          target.endsWith('.md') &&
          !anchorsIn(target).has(link.anchor)
        ) {
          broken.push(`${where}: no heading with that anchor`);
        }
      }
    }
    expect(broken).toEqual([]);
  });
});

describe('markdown-links', () => {
  it('slugs headings as GitHub does, and leaves out links in code', () => {
    const doc = [
      '# The `hal` command',
      '## 8. Authentication',
      '## Authentication',
      'See [it](other.md#x) and `[not](this.md)`, [web](https://example.com).',
      '```md',
      '[fenced](nope.md)',
      '```',
      '<a id="custom"></a>',
    ].join('\n');
    expect([...anchorsOf(doc)]).toEqual([
      'the-hal-command',
      '8-authentication',
      'authentication',
      'custom',
    ]);
    expect(relativeLinks(doc)).toEqual([{ line: 4, path: 'other.md', anchor: 'x' }]);
  });
});
