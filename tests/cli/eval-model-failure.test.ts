// `hal eval` with a model that never answers: a closed port on 127.0.0.1, a host under .invalid,
// an endpoint (the fake one, over real HTTP) that refuses every request. Each is a failed run
// (exit 1) naming the cause once, not a score; eval.json keeps it apart from the task failures.
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import type { EvalReport } from '@hal/eval';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import type { FakeOpenAIServer } from '../helpers/fake-openai-server.js';
import { captureIO } from './capture-io.js';

let dir = '';
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-eval-model-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});
let server: FakeOpenAIServer | undefined;
afterEach(async () => {
  await server?.close();
  server = undefined;
});

/** A port on 127.0.0.1 that nothing listens on: taken, then let go. */
async function closedPort(): Promise<number> {
  const probe = createServer();
  await new Promise<void>((resolve) => probe.listen(0, '127.0.0.1', resolve));
  const { port } = probe.address() as AddressInfo;
  await new Promise<void>((resolve) => probe.close(() => resolve()));
  return port;
}

const occurrences = (text: string, word: string) => text.split(word).length - 1;
const run = ['--tasks', 'precision', '--trials', '2'];

describe('hal eval with a model that never answers', () => {
  it('exits 1 naming ECONNREFUSED once; the table and eval.json set it apart, the oracle scores as ever', async () => {
    const port = await closedPort();
    const out = join(dir, 'refused');
    const io = captureIO({});
    const base = `http://127.0.0.1:${port}/v1`;
    const args = ['eval', '--agent', 'oracle,openai:gpt-4o-mini', '--base-url', base];
    const code = await runHal([...args, ...run, '--out', out], io);
    expect(code, io.stderr()).toBe(1);
    const stderr = io.stderr();
    expect(stderr).toMatch(
      /hal: FAILED: the model could not be used, so its trials are not scored: openai:gpt-4o-mini: model failed \(NETWORK\) in 1 trial, \d+ not run: NETWORK: request to http:\/\/127\.0\.0\.1:\d+\/v1\/chat\/completions failed: .*ECONNREFUSED/,
    );
    expect(occurrences(stderr, 'ECONNREFUSED')).toBe(1);
    expect(stderr).toMatch(/openai:gpt-4o-mini precision\/\S+ seed 1: model failed \(NETWORK\)/);
    expect(stderr).not.toMatch(/FAIL \(displacement/);
    const table = io.stdout();
    expect(table).toMatch(/^agent .* model\n/);
    expect(table).toMatch(/\noracle\s+100% \d+\/\d+ .* ok\n/);
    expect(table).toMatch(
      /\nopenai:gpt-4o-mini\s+-\s+-\s+-\s+.*model failed \(NETWORK\) in 1 trial/,
    );
    const report = JSON.parse(await readFile(join(out, 'eval.json'), 'utf8')) as EvalReport;
    const [oracle, model] = report.scores.agents;
    expect(report.version).toBe(3);
    expect(oracle?.modelFailure).toBeNull();
    expect(model?.modelFailure).toMatchObject({ code: 'NETWORK', trials: 1 });
    expect(model?.modelFailure?.message).toContain('ECONNREFUSED');
    expect(model?.overall.trials).toBe(0);
    expect(model?.trials[0]).toMatchObject({ success: false, failures: [] });
  }, 60_000);

  it('names ENOTFOUND and the host for an endpoint no resolver knows', async () => {
    const io = captureIO({});
    const base = 'http://model.hal-test.invalid/v1';
    const code = await runHal(['eval', '--agent', 'openai:m', '--base-url', base, ...run], io);
    expect(code, io.stderr()).toBe(1);
    expect(io.stderr()).toMatch(/hal: FAILED: .*NETWORK: .*ENOTFOUND.*model\.hal-test\.invalid/);
    expect(occurrences(io.stderr(), 'ENOTFOUND')).toBe(1);
  }, 60_000);

  it('names the HTTP status of an endpoint that refuses every request (no key)', async () => {
    server = await startFakeOpenAIServer([
      { status: 401, body: '{"error":{"message":"Incorrect API key provided"}}' },
    ]);
    const io = captureIO({});
    const code = await runHal(
      ['--json', 'eval', '--agent', 'openai:m', '--base-url', server.baseUrl, ...run],
      io,
    );
    expect(code).toBe(1);
    expect(io.stderr()).toContain('HTTP 401');
    expect(io.stderr()).toContain('no API key was given');
    const report = io.jsonLines()[0] as EvalReport;
    expect(report.scores.agents[0]?.modelFailure).toMatchObject({ code: 'HTTP' });
    // the first trial failed before the model ever answered: the others were not run
    expect(server.requests).toHaveLength(1);
  }, 60_000);

  it('scores a model that answers, even one that fails every task, and exits 0', async () => {
    server = await startFakeOpenAIServer([{ content: 'I will not move.' }]);
    const io = captureIO({});
    const code = await runHal(
      ['--json', 'eval', '--agent', 'openai:m', '--base-url', server.baseUrl, ...run],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const report = io.jsonLines()[0] as EvalReport;
    expect(report.scores.agents[0]?.modelFailure).toBeNull();
    expect(report.scores.agents[0]?.overall.trials).toBeGreaterThan(0);
    expect(report.scores.agents[0]?.overall.successes).toBe(0);
  }, 60_000);
});
