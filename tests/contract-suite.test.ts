import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { runProcess } from './helpers/run-process.js';

const vitestCli = createRequire(import.meta.url).resolve('vitest/vitest.mjs');

/** Runs the contract suite on a fixture HAL in its own vitest; returns the titles that failed. */
async function failedContractTests(name: string): Promise<string[]> {
  const fixture = fileURLToPath(new URL(`./fixtures/${name}/`, import.meta.url));
  const run = await runProcess(
    process.execPath,
    [vitestCli, 'run', '--config', `${fixture}vitest.config.ts`, '--reporter', 'json'],
    { cwd: fixture, timeoutMs: 50_000 },
  );
  expect(run.status).toBe(1);
  const report = JSON.parse(run.stdout.slice(run.stdout.indexOf('{'))) as {
    testResults: Array<{ assertionResults: Array<{ title: string; status: string }> }>;
  };
  return report.testResults
    .flatMap((file) => file.assertionResults)
    .filter((test) => test.status === 'failed')
    .map((test) => test.title)
    .sort();
}

describe('the HAL contract suite', () => {
  it('fails a HAL whose reads bypass the boundary, on exactly the boundary and lifecycle tests', async () => {
    expect(await failedContractTests('lenient-hal')).toEqual([
      'never throws from log, whatever it is given, and keeps working',
      'refuses every call with NOT_READY after cleanup(), and stays not ready',
      'refuses every call with NOT_READY before initialize(), and the safety reads answer',
      'rejects scan with an unknown mode with INVALID_PARAMETER, whatever sensors it has',
    ]);
  });

  it('fails a HAL whose rotate("left") turns clockwise, on exactly the direction tests', async () => {
    expect(await failedContractTests('mirrored-hal')).toEqual([
      'rotate("left", 90) turns counter-clockwise to +pi/2, then forward goes +y',
      'rotate("right", 90) turns clockwise to -pi/2',
    ]);
  });
});
