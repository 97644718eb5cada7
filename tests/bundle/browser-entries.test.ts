// The browser entries of the packages a browser uses import nothing Node-only or native
// statically: Node built-ins, ws, serialport and sharp are loaded with import() (or a variable
// specifier) by the functions that need them, so a bundler leaves them out. This reads the source
// import graph; tests/publish bundles the packed packages with Vite as well.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

const packages = new URL('../../packages/', import.meta.url);

/** The modules a file imports statically (`import type` and `await import()` left out). */
function staticImports(file: URL): { local: URL[]; bare: string[] } {
  const source = readFileSync(file, 'utf8');
  const local: URL[] = [];
  const bare: string[] = [];
  const pattern = /^(?:import|export)\s+(?!type\b)[^;]*?from\s+'([^']+)';/gms;
  for (const match of source.matchAll(pattern)) {
    const specifier = match[1] as string;
    if (specifier.startsWith('.')) local.push(new URL(specifier.replace(/\.js$/, '.ts'), file));
    else bare.push(specifier);
  }
  return { local, bare };
}

/** Every source file an entry reaches statically, and the bare modules they import. */
function reachable(entry: string): { files: string[]; bare: string[] } {
  const files = new Set<string>();
  const bare = new Set<string>();
  const queue = [new URL(entry, packages)];
  while (queue.length > 0) {
    const file = queue.pop() as URL;
    if (files.has(file.href)) continue;
    files.add(file.href);
    const found = staticImports(file);
    queue.push(...found.local);
    for (const specifier of found.bare) bare.add(specifier);
  }
  return { files: [...files], bare: [...bare].sort() };
}

describe('the browser entries import nothing Node-only statically', () => {
  it('@hal/physical: node:dgram, node:crypto and serialport load on use', () => {
    const { files, bare } = reachable('physical/src/index.ts');
    expect(files.length).toBeGreaterThan(10);
    expect(bare).toEqual([
      '@hal/kinematics',
      '@hal/runtime',
      '@hal/types',
      'crc/calculators/crc16ccitt',
      'zod',
    ]);
  });

  it('@hal/simulation: sharp is named to no bundler (a variable specifier)', () => {
    const { files, bare } = reachable('simulation/src/index.ts');
    expect(files.length).toBeGreaterThan(20);
    expect(bare).toEqual(['@hal/kinematics', '@hal/runtime', '@hal/types', 'zod']);
    for (const href of files) {
      expect(readFileSync(new URL(href), 'utf8'), href).not.toMatch(/import\(\s*['"]sharp['"]/);
    }
  });

  it('@hal/runtime: the HAL class, the forwarding base and the serving pieces reach only the contract', () => {
    const { files, bare } = reachable('runtime/src/index.ts');
    expect(files.length).toBeGreaterThan(9);
    expect(bare).toEqual(['@hal/types']);
  });

  it('@hal/remote: the client entry reaches neither ws nor the server', () => {
    const { files, bare } = reachable('remote/src/index.ts');
    expect(files.length).toBeGreaterThan(5);
    expect(files.some((f) => f.includes('/server/'))).toBe(false);
    expect(bare).toEqual(['@hal/runtime', '@hal/types', 'zod']);
  });

  it('@hal/fleet: the fleet modes reach neither NATS nor the device manager', () => {
    const { files, bare } = reachable('fleet/src/index.ts');
    expect(files.length).toBeGreaterThan(5);
    expect(files.some((f) => f.includes('/node/'))).toBe(false);
    expect(bare).toEqual(['@hal/types', 'zod']);
  });

  it('the browser demo reaches only the browser entries (@hal/fleet, not @hal/fleet/node)', () => {
    const { files, bare } = reachable('../apps/sim-demo/src/main.ts');
    expect(files.some((f) => f.includes('/fleet/demo-fleet.ts'))).toBe(true);
    expect(bare).toEqual([
      '@hal/agent',
      '@hal/fleet',
      '@hal/hybrid',
      '@hal/kinematics',
      '@hal/navigation',
      '@hal/perception',
      '@hal/remote',
      '@hal/simulation',
      '@hal/simulation/three',
      '@hal/types',
      'three',
      'three/addons/controls/OrbitControls.js',
    ]);
  });

  it('@hal/perception: sharp is named to no bundler (a variable specifier)', () => {
    const { files, bare } = reachable('perception/src/index.ts');
    expect(files.length).toBeGreaterThan(20);
    expect(bare).toEqual(['@hal/agent', '@hal/kinematics', '@hal/types', 'jpeg-js', 'zod']);
    for (const href of files) {
      expect(readFileSync(new URL(href), 'utf8'), href).not.toMatch(/import\(\s*['"]sharp['"]/);
    }
  });

  it('@hal/remote/server keeps ws and the Node built-ins (so the check above can fail)', () => {
    const { bare } = reachable('remote/src/server/index.ts');
    expect(bare).toEqual(expect.arrayContaining(['node:crypto', 'node:http', 'ws']));
  });
});
