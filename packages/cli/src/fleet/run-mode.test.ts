import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolveRunMode } from './run-mode.js';

let dir: string;
const file = async (name: string, config: unknown) => {
  const path = join(dir, name);
  await writeFile(path, JSON.stringify(config));
  return path;
};
const devices = [{ type: 'simulated', id: 'sim-1' }];

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-run-mode-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

describe('resolveRunMode', () => {
  it('takes --mode over the config file', async () => {
    const path = await file('sync.json', { mode: 'synchronized', devices });
    await expect(resolveRunMode('leader-follower', path)).resolves.toBe('leader-follower');
    await expect(resolveRunMode('synchronized', undefined)).resolves.toBe('synchronized');
  });

  it("takes the config file's mode when --mode is not given", async () => {
    const sync = await file('sync.json', { mode: 'synchronized', devices });
    const lead = await file('lead.json', { mode: 'leader-follower', devices });
    await expect(resolveRunMode(undefined, sync)).resolves.toBe('synchronized');
    await expect(resolveRunMode(undefined, lead)).resolves.toBe('leader-follower');
  });

  it('refuses as a usage error a config file whose mode runs nothing, and no mode at all', async () => {
    const path = await file('independent.json', { devices });
    await expect(resolveRunMode(undefined, path)).rejects.toMatchObject({
      code: 'USAGE',
      message: expect.stringContaining('its mode is "independent"'),
    });
    await expect(resolveRunMode(undefined, undefined)).rejects.toMatchObject({
      code: 'USAGE',
      message: expect.stringContaining('give --mode synchronized or --mode leader-follower'),
    });
  });
});
