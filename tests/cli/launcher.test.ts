// scripts/hal.js, the `hal` of a checkout (`pnpm hal`): it runs one bundled file, rebuilt only when
// a file it was built from is newer than the bundle.
import { spawnSync } from 'node:child_process';
import { readFileSync, statSync, utimesSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const root = fileURLToPath(new URL('../../', import.meta.url));
const bundle = `${root}packages/cli/.bundle/hal.js`;
const source = `${root}packages/cli/src/io.ts`;

function hal(...args: string[]): { status: number | null; stdout: string; stderr: string } {
  return spawnSync(process.execPath, ['scripts/hal.js', ...args], {
    cwd: root,
    encoding: 'utf8',
    timeout: 60_000,
  });
}

describe('the checkout launcher (scripts/hal.js)', () => {
  it('is what the root "pnpm hal" script runs', () => {
    const manifest = JSON.parse(readFileSync(`${root}package.json`, 'utf8')) as {
      scripts: Record<string, string>;
    };
    expect(manifest.scripts['hal']).toBe('node scripts/hal.js');
  });

  it('runs the CLI with its arguments and exit code', () => {
    const help = hal('--help');
    expect(help.status, help.stderr).toBe(0);
    expect(help.stdout).toContain('Usage: hal');
    const status = hal('--json', 'status', '--sim');
    expect(status.status, status.stderr).toBe(0);
    expect(JSON.parse(status.stdout.split('\n')[0]!)).toMatchObject({
      device: { mode: 'simulation' },
    });
    expect(hal('drive', 'forward', 'far', '--sim').status).toBe(2);
  });

  it('reuses a fresh bundle and rebuilds it once a source is newer', () => {
    expect(hal('--version').status).toBe(0);
    const before = statSync(bundle).mtimeMs;
    const again = hal('--version');
    expect(again.stderr).not.toContain('bundling');
    expect(statSync(bundle).mtimeMs).toBe(before);

    const original = statSync(source);
    const now = Date.now() / 1000;
    utimesSync(bundle, now - 20, now - 20);
    utimesSync(source, original.atime, now - 10);
    try {
      const rebuilt = hal('--version');
      expect(rebuilt.status, rebuilt.stderr).toBe(0);
      expect(rebuilt.stderr).toContain('bundling');
      expect(statSync(bundle).mtimeMs).toBeGreaterThan((now - 10) * 1000);
    } finally {
      utimesSync(source, original.atime, original.mtime);
    }
  });
});
