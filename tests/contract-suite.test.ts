import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const vitestCli = createRequire(import.meta.url).resolve('vitest/vitest.mjs');
const fixture = fileURLToPath(new URL('./fixtures/mirrored-hal/', import.meta.url));

describe('the HAL contract suite', () => {
  it('fails a HAL whose rotate("left") turns clockwise, on exactly the direction tests', () => {
    const run = spawnSync(
      process.execPath,
      [vitestCli, 'run', '--config', `${fixture}vitest.config.ts`, '--reporter', 'json'],
      { cwd: fixture, encoding: 'utf8', timeout: 50_000 },
    );
    expect(run.status).toBe(1);
    const report = JSON.parse(run.stdout.slice(run.stdout.indexOf('{'))) as {
      testResults: Array<{ assertionResults: Array<{ title: string; status: string }> }>;
    };
    const failed = report.testResults
      .flatMap((file) => file.assertionResults)
      .filter((test) => test.status === 'failed')
      .map((test) => test.title);
    expect(failed.sort()).toEqual([
      'rotate("left", 90) turns counter-clockwise to +pi/2, then forward goes +y',
      'rotate("right", 90) turns clockwise to -pi/2',
    ]);
  });
});
