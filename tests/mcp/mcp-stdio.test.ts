import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { afterEach, describe, expect, it } from 'vitest';
import { serverCommand } from './client.js';
import { driveOverMcp } from './scenario.js';

let client: Client | undefined;
afterEach(async () => {
  await client?.close();
  client = undefined;
});

async function connect(args: string[] = []): Promise<Client> {
  client = new Client({ name: 'hal-test', version: '1.0.0' });
  await client.connect(new StdioClientTransport({ ...serverCommand(args), stderr: 'ignore' }));
  return client;
}

describe('hal mcp over stdio (the server process, the SDK client)', () => {
  it('lists the tools, moves, reads the pose, gets a frame, refuses bad arguments and e-stops', async () => {
    await driveOverMcp(await connect());
  });

  it('serves the state, capabilities and the map of the simulated arena as resources', async () => {
    const c = await connect(['--map', 'obstacles']);
    const { resources } = await c.listResources();
    expect(resources.map((r) => r.uri)).toEqual([
      'robot://state',
      'robot://capabilities',
      'robot://map',
      'robot://events',
      'robot://camera',
    ]);
    const caps = JSON.parse(
      ((await c.readResource({ uri: 'robot://capabilities' })).contents[0] as { text: string })
        .text,
    );
    expect(caps).toMatchObject({ device: { mode: 'simulation' }, limits: { wheelDiameterCm: 6 } });
    expect(caps.tools).toContain('move_to');
    const map = JSON.parse(
      ((await c.readResource({ uri: 'robot://map' })).contents[0] as { text: string }).text,
    );
    expect(map.map.obstacles.length).toBeGreaterThan(0);
    const camera = (await c.readResource({ uri: 'robot://camera' })).contents[0] as {
      blob: string;
      mimeType: string;
    };
    expect(camera.mimeType).toBe('image/jpeg');
    expect(Buffer.from(camera.blob, 'base64').subarray(0, 2)).toEqual(Buffer.from([0xff, 0xd8]));
    await expect(c.readResource({ uri: 'robot://nothing' })).rejects.toThrow(/no resource/);
  });

  it('applies the leash given on the command line', async () => {
    const c = await connect(['--max-distance', '0.1']);
    const result = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 50 } });
    expect(result.isError).toBe(true);
    expect(JSON.stringify(result.content)).toContain('LEASH_DISTANCE');
  });
});
