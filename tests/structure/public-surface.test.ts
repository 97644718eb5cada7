import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import {
  readPublicSurface,
  SURFACE_COMMAND,
  SURFACE_FILE,
  surfaceChanges,
  type PublicSurface,
} from './public-surface.js';

// Each package's public surface is written down in public-surface.json, so adding or removing an
// exported name is a change someone makes on purpose (and reviews in the diff of that file).

const root = fileURLToPath(new URL('../../', import.meta.url));

describe('the public surface of the packages', () => {
  const current = readPublicSurface(root);

  it('is read from every entry of every package', () => {
    // the reader follows re-exports, or an empty surface would agree with an empty file
    expect(Object.keys(current)).toContain('@hal/types');
    expect(current['@hal/physical']?.['./testing']).toBeDefined();
    expect(current['@hal/simulation']?.['.']?.['SimulationHAL']).toBe('value, type');
    expect(current['@hal/types']?.['.']?.['HALToolResult']).toBe('type');
  });

  it('is the one written in public-surface.json', () => {
    const committed = JSON.parse(readFileSync(join(root, SURFACE_FILE), 'utf8')) as PublicSurface;
    const { added, removed } = surfaceChanges(committed, current);
    const message = [
      `the exports differ from ${SURFACE_FILE}; if the change is meant, run: ${SURFACE_COMMAND}`,
      ...added.map((line) => `+ ${line}`),
      ...removed.map((line) => `- ${line}`),
    ].join('\n');
    expect({ added, removed }, message).toStrictEqual({ added: [], removed: [] });
  });
});

describe('surfaceChanges', () => {
  it('names what one surface adds and removes against the other', () => {
    const before: PublicSurface = { '@hal/x': { '.': { a: 'value', b: 'type' } } };
    const after: PublicSurface = { '@hal/x': { '.': { a: 'value, type', c: 'value' } } };
    expect(surfaceChanges(before, after)).toStrictEqual({
      added: ['@hal/x . a (value, type)', '@hal/x . c (value)'],
      removed: ['@hal/x . a (value)', '@hal/x . b (type)'],
    });
  });
});
