// hal mcp --udp against the firmware core running as the emulated robot: the whole chain an MCP
// client drives a real robot through, with the protocol 1.1 key.
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { callTool, serverCommand } from './client.js';

afterAll(stopAllEmulators);

const KEY = '00112233445566778899aabbccddeeff';

describe('hal mcp --udp against the emulated robot', () => {
  it('offers what the robot reported, moves it, reads its pose and e-stops it', async () => {
    const emulator = await startEmulator({ key: KEY, pty: false, hostTimeoutMs: 10_000 });
    const client = new Client({ name: 'hal-test', version: '1.0.0' });
    const command = serverCommand(['--udp', `127.0.0.1:${emulator.udpPort}`]);
    await client.connect(
      new StdioClientTransport({
        ...command,
        env: { ...(process.env as Record<string, string>), HAL_KEY: KEY },
        stderr: 'ignore',
      }),
    );
    try {
      const names = (await client.listTools()).tools.map((t) => t.name);
      expect(names).toEqual(expect.arrayContaining(['move_forward', 'set_led', 'emergency_stop']));
      expect(names).not.toContain('capture_frame'); // the emulated cube has no camera
      const moved = await callTool(client, 'move_forward', { distanceCm: 3 });
      expect(moved.isError, moved.text).toBe(false);
      const pose = await callTool(client, 'get_pose');
      expect((pose.json['position'] as { x: number }).x).toBeCloseTo(0.03, 2);
      const map = await client.readResource({ uri: 'robot://map' });
      expect(JSON.parse((map.contents[0] as { text: string }).text)).toMatchObject({ map: null });
      expect((await callTool(client, 'emergency_stop', { reason: 'test' })).isError).toBe(false);
      const state = await callTool(client, 'is_emergency_stopped');
      expect(state.json).toEqual({ emergencyStopped: true });
      expect(await callTool(client, 'move_forward', { distanceCm: 3 })).toMatchObject({
        isError: true,
        json: { code: 'EMERGENCY_STOPPED' },
      });
    } finally {
      await client.close();
      await emulator.stop();
    }
  });
});
