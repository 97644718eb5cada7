// The order vitest starts test files in: the longest first, so that a file of minutes does not
// start last and run alone while the other workers sit idle. vitest's own order does this only
// from its results cache (node_modules/.vite/vitest), which a fresh checkout, as on CI, has not:
// there it starts the largest files first, whatever they take. So the files known to take longest
// are listed here with their time from a full run on a 2-core machine. The list only orders the
// run: a file missing from it, or a time gone stale, costs wall time, never a result.
import { relative } from 'node:path';
import { BaseSequencer } from 'vitest/node';
import type { TestSpecification } from 'vitest/node';

/** Seconds each of the slowest files took in a full run (`vitest run`, four workers, two cores). */
export const SLOW_FILES: Readonly<Record<string, number>> = {
  'tests/publish/installs.test.ts': 199,
  'tests/docs/doc-commands.test.ts': 173,
  'packages/cli/src/commands/agent.test.ts': 119,
  'tests/cli/eval-emulator.test.ts': 81,
  'packages/cli/src/commands/eval.test.ts': 77,
  'tests/cli/local-model-file.test.ts': 75,
  'tests/publish/packages.test.ts': 71,
  'tests/cli/serve-nats.test.ts': 70,
  'tests/cli/serve-udp-nats.test.ts': 52,
  'tests/physical/soak.test.ts': 45,
  'packages/agent-local/src/every-tool.test.ts': 42,
  'tests/compliance/cli.test.ts': 41,
  'tests/discovery/discovery.test.ts': 37,
  'tests/agent/example-app.test.ts': 36,
  'tests/setup/missing-tools.test.ts': 36,
  'packages/eval/src/agents/agents.test.ts': 35,
  'tests/cli/look.test.ts': 34,
};

export class SlowFirstSequencer extends BaseSequencer {
  /** Milliseconds `spec` is expected to take: the last run's, else the list's, else unknown. */
  private expectedMs(spec: TestSpecification): number | undefined {
    const file = relative(this.ctx.config.root, spec.moduleId).replaceAll('\\', '/');
    const cached = this.ctx.cache.getFileTestResults(`${spec.project.name}:${file}`);
    if (cached !== undefined) return cached.duration;
    const listed = SLOW_FILES[file];
    return listed === undefined ? undefined : listed * 1000;
  }

  override async sort(files: TestSpecification[]): Promise<TestSpecification[]> {
    // vitest's order (failed first, then by time or size), then the files expected to take long
    // moved ahead of the rest, longest first; the sort is stable, so the rest keep vitest's order
    const base = await super.sort(files);
    const expected = new Map(base.map((spec) => [spec, this.expectedMs(spec) ?? -1]));
    return [...base].sort((a, b) => expected.get(b)! - expected.get(a)!);
  }
}
