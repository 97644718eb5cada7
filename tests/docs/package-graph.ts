// The packages under packages/ and their dependencies on one another, read from their
// package.json files when the test runs, so a package added later is held to the docs too.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

/** Package name (`@hal/types`) to the workspace packages it depends on. */
export type PackageGraph = ReadonlyMap<string, ReadonlySet<string>>;

interface Manifest {
  name: string;
  dependencies?: Record<string, string>;
  peerDependencies?: Record<string, string>;
}

/**
 * Every package under `packages/` with its `dependencies` and `peerDependencies` on other
 * `@hal/*` packages: what a user installs with it. Test-only (`devDependencies`) ones are not
 * part of the architecture and are left out.
 */
export function readPackageGraph(repoRoot: string): PackageGraph {
  const root = join(repoRoot, 'packages');
  const graph = new Map<string, Set<string>>();
  for (const folder of readdirSync(root)) {
    const file = join(root, folder, 'package.json');
    if (!existsSync(file)) continue;
    const manifest = JSON.parse(readFileSync(file, 'utf8')) as Manifest;
    const names = Object.keys({ ...manifest.dependencies, ...manifest.peerDependencies });
    graph.set(manifest.name, new Set(names.filter((name) => name.startsWith('@hal/'))));
  }
  return graph;
}

/** Everything `from` reaches through the graph's arrows, itself excluded. */
export function reachable(graph: PackageGraph, from: string): Set<string> {
  const seen = new Set<string>();
  const pending = [...(graph.get(from) ?? [])];
  for (let next = pending.pop(); next !== undefined; next = pending.pop()) {
    if (seen.has(next)) continue;
    seen.add(next);
    pending.push(...(graph.get(next) ?? []));
  }
  return seen;
}

/** A dependency circle as `a -> b -> a`, or undefined when the graph has none. */
export function findCircle(graph: PackageGraph): string | undefined {
  const done = new Set<string>();
  const path: string[] = [];
  const visit = (name: string): string | undefined => {
    const at = path.indexOf(name);
    if (at >= 0) return [...path.slice(at), name].join(' -> ');
    if (done.has(name)) return undefined;
    path.push(name);
    for (const dep of graph.get(name) ?? []) {
      const circle = visit(dep);
      if (circle !== undefined) return circle;
    }
    path.pop();
    done.add(name);
    return undefined;
  };
  for (const name of graph.keys()) {
    const circle = visit(name);
    if (circle !== undefined) return circle;
  }
  return undefined;
}
