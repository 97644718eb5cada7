import { join, relative } from 'node:path';
import { defaultModelFile, SMALL_MODEL_TOOLS } from '@hal/agent-local';
import { describe, expect, it } from 'vitest';
import { modelChoice } from './model-choice.js';

const env = { XDG_CACHE_HOME: join('/tmp', 'hal-cache') };

describe('modelChoice', () => {
  it('offers the default model the skills when no file and no --tools is given', () => {
    expect(modelChoice({}, env)).toEqual({ kind: 'local', profile: 'skills' });
  });

  it('runs the default file given by its path as the default, however the path is written', () => {
    const file = defaultModelFile(env);
    expect(modelChoice({ modelFile: file }, env)).toEqual({ kind: 'local', profile: 'skills' });
    const roundabout = relative(process.cwd(), join(file, '..', '..', 'models', 'x', '..'));
    const written = join(roundabout, file.split('/').at(-1) ?? '');
    expect(modelChoice({ modelFile: written }, env)).toEqual({ kind: 'local', profile: 'skills' });
  });

  it('offers the default model a few HAL tools when asked for the primitives', () => {
    expect(modelChoice({ tools: 'primitives' }, env)).toEqual({
      kind: 'local',
      profile: 'primitives',
      offerTools: SMALL_MODEL_TOOLS,
    });
    expect(modelChoice({ tools: 'all' }, env)).toEqual({ kind: 'local', profile: 'all' });
  });

  it('offers every HAL tool to any other GGUF, unless --tools says otherwise', () => {
    expect(modelChoice({ modelFile: '/models/other.gguf' }, env)).toEqual({
      kind: 'local',
      modelFile: '/models/other.gguf',
      profile: 'primitives',
    });
    expect(modelChoice({ modelFile: '/m/o.gguf', tools: 'rotate' }, env)).toMatchObject({
      profile: 'primitives',
      offerTools: ['rotate'],
    });
    expect(modelChoice({ modelFile: '/m/o.gguf', tools: 'skills' }, env)).toMatchObject({
      profile: 'skills',
    });
  });

  it('gives an endpoint the primitives unless --tools names a profile', () => {
    const endpoint = { baseUrl: 'http://127.0.0.1:1/v1', model: 'm' };
    expect(modelChoice(endpoint, env)).toMatchObject({ kind: 'endpoint', profile: 'primitives' });
    expect(modelChoice({ ...endpoint, tools: 'skills' }, env)).toMatchObject({ profile: 'skills' });
    expect(modelChoice({ ...endpoint, tools: 'move_forward,rotate' }, env)).toMatchObject({
      profile: 'primitives',
      tools: ['move_forward', 'rotate'],
    });
  });

  it('refuses a profile inside a list of tool names, and an empty list', () => {
    expect(() => modelChoice({ tools: 'skills,move_forward' }, env)).toThrow(/is a profile/);
    expect(() => modelChoice({ tools: ' , ' }, env)).toThrow(/must be a profile/);
  });
});
