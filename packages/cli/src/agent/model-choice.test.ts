import { join, relative } from 'node:path';
import { defaultModelFile, SMALL_MODEL_TOOLS } from '@hal/agent-local';
import { describe, expect, it } from 'vitest';
import { modelChoice } from './model-choice.js';

const env = { XDG_CACHE_HOME: join('/tmp', 'hal-cache') };

describe('modelChoice', () => {
  it('runs the default model with its few tools when no file is given', () => {
    expect(modelChoice({}, env)).toEqual({ kind: 'local', offerTools: SMALL_MODEL_TOOLS });
  });

  it('runs the default file given by its path as the default, however the path is written', () => {
    const file = defaultModelFile(env);
    expect(modelChoice({ modelFile: file }, env)).toEqual({
      kind: 'local',
      offerTools: SMALL_MODEL_TOOLS,
    });
    const roundabout = relative(process.cwd(), join(file, '..', '..', 'models', 'x', '..'));
    const written = join(roundabout, file.split('/').at(-1) ?? '');
    expect(modelChoice({ modelFile: written }, env)).toEqual({
      kind: 'local',
      offerTools: SMALL_MODEL_TOOLS,
    });
  });

  it('offers every tool to any other GGUF, unless --tools says otherwise', () => {
    expect(modelChoice({ modelFile: '/models/other.gguf' }, env)).toEqual({
      kind: 'local',
      modelFile: '/models/other.gguf',
    });
    expect(modelChoice({ modelFile: '/m/o.gguf', tools: 'rotate' }, env)).toMatchObject({
      offerTools: ['rotate'],
    });
  });
});
