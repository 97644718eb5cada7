import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { readFleetConfigFile, selectDevices } from './fleet-config-file.js';

let dir: string;

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-fleet-config-'));
});
afterAll(() => rm(dir, { recursive: true, force: true }));

async function file(name: string, text: string): Promise<string> {
  const path = join(dir, name);
  await writeFile(path, text);
  return path;
}

describe('a fleet config file', () => {
  it('is read into the device manager config, with its defaults filled in', async () => {
    const path = await file(
      'good.json',
      JSON.stringify({
        devices: [
          { type: 'simulated', id: 'sim' },
          { type: 'physical', id: 'cube', connection: { type: 'wifi', host: '127.0.0.1' } },
        ],
      }),
    );
    const config = await readFleetConfigFile(path);
    expect(config.devices.map((d) => [d.id, d.type])).toEqual([
      ['sim', 'simulated'],
      ['cube', 'physical'],
    ]);
    expect(config).toMatchObject({ mode: 'independent', offlineAfterMs: 3000 });
  });

  it('that is missing is NOT_FOUND and one that is not JSON is a USAGE error', async () => {
    await expect(readFleetConfigFile(join(dir, 'absent.json'))).rejects.toMatchObject({
      name: 'CliError',
      code: 'NOT_FOUND',
    });
    await expect(readFleetConfigFile(await file('bad.json', '{ devices: ['))).rejects.toMatchObject(
      { name: 'CliError', code: 'USAGE', message: expect.stringContaining('not JSON') },
    );
  });

  it('that the schema refuses names every problem by its path', async () => {
    const path = await file(
      'invalid.json',
      JSON.stringify({
        devices: [
          { type: 'physical', id: 'cube', connection: { type: 'wifi', udpPort: 70_000 } },
          { type: 'robot', id: 'x' },
        ],
        telemetryRateHz: 0,
      }),
    );
    const refused = readFleetConfigFile(path);
    await expect(refused).rejects.toMatchObject({ name: 'HalError', code: 'INVALID_PARAMETER' });
    const message = await refused.catch((e: unknown) => (e as Error).message);
    expect(message).toContain('devices.0.connection.udpPort');
    expect(message).toContain('devices.1.type');
    expect(message).toContain('telemetryRateHz');
    const twice = await file(
      'twice.json',
      JSON.stringify({
        devices: [
          { type: 'simulated', id: 'a' },
          { type: 'simulated', id: 'a' },
        ],
      }),
    );
    await expect(readFleetConfigFile(twice)).rejects.toThrow('devices.1.id: duplicate id "a"');
  });

  it('is narrowed to the devices named, and naming one it lacks is a USAGE error', async () => {
    const config = await readFleetConfigFile(
      await file(
        'three.json',
        JSON.stringify({ devices: ['a', 'b', 'c'].map((id) => ({ type: 'simulated', id })) }),
      ),
    );
    expect(selectDevices(config, []).devices.map((d) => d.id)).toEqual(['a', 'b', 'c']);
    expect(selectDevices(config, ['c', 'a']).devices.map((d) => d.id)).toEqual(['a', 'c']);
    expect(() => selectDevices(config, ['a', 'z'])).toThrow(
      /--device z: not in the config file \(it has a, b, c\)/,
    );
  });
});
