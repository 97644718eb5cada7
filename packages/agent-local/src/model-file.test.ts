import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { checkModelFile, DEFAULT_MODEL_NAME, defaultModelFile } from './model-file.js';

describe('checkModelFile', () => {
  let dir: string;
  beforeAll(async () => {
    dir = await mkdtemp(join(tmpdir(), 'hal-model-'));
  });
  afterAll(async () => {
    await rm(dir, { recursive: true, force: true });
  });

  it('says a missing default model is fetched by hal model pull', async () => {
    const path = join(dir, 'nope.gguf');
    await expect(checkModelFile(path, true)).rejects.toMatchObject({
      code: 'MODEL_MISSING',
      message: expect.stringContaining('run `hal model pull` to fetch it'),
    });
  });

  it('refuses a file that is not GGUF, saying what it starts with', async () => {
    const path = join(dir, 'text.gguf');
    await writeFile(path, 'hello world');
    await expect(checkModelFile(path, false)).rejects.toMatchObject({
      code: 'MODEL_INVALID',
      message: expect.stringContaining('"hell"'),
    });
  });

  it('refuses a directory', async () => {
    await expect(checkModelFile(dir, false)).rejects.toMatchObject({ code: 'MODEL_INVALID' });
  });

  it('accepts a file that starts with the GGUF magic', async () => {
    const path = join(dir, 'head.gguf');
    await writeFile(path, Buffer.from('GGUF\x03\x00\x00\x00', 'latin1'));
    await expect(checkModelFile(path, false)).resolves.toBeUndefined();
  });
});

describe('defaultModelFile', () => {
  it('lives under XDG_CACHE_HOME when it is set, else ~/.cache', () => {
    expect(defaultModelFile({ XDG_CACHE_HOME: '/c' })).toBe(`/c/hal/models/${DEFAULT_MODEL_NAME}`);
    expect(defaultModelFile({})).toMatch(new RegExp(`\\.cache/hal/models/${DEFAULT_MODEL_NAME}$`));
  });
});
