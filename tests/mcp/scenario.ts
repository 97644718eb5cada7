// The same session over every transport: list, move, read, frame, bad arguments, e-stop.
import type { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { expect } from 'vitest';
import { callTool } from './client.js';

export async function driveOverMcp(client: Client): Promise<void> {
  const { tools } = await client.listTools();
  const names = tools.map((t) => t.name);
  expect(names).toEqual(
    expect.arrayContaining(['move_forward', 'get_pose', 'capture_frame', 'emergency_stop']),
  );
  const move = tools.find((t) => t.name === 'move_forward');
  expect(move?.inputSchema).toMatchObject({
    type: 'object',
    properties: { distanceCm: { type: 'number', maximum: 188.4 } },
  });

  const moved = await callTool(client, 'move_forward', { distanceCm: 20 });
  expect(moved.isError, moved.text).toBe(false);
  expect(moved.json).toMatchObject({ success: true });

  const pose = await callTool(client, 'get_pose');
  expect((pose.json['position'] as { x: number }).x).toBeCloseTo(0.2, 2);

  const frame = await callTool(client, 'capture_frame');
  expect(frame.images).toHaveLength(1);
  expect(frame.images[0]?.mimeType).toBe('image/jpeg');
  expect(Buffer.from(frame.images[0]?.data ?? '', 'base64').subarray(0, 2)).toEqual(
    Buffer.from([0xff, 0xd8]),
  );

  const bad = await callTool(client, 'move_forward', { distanceCm: 'far' });
  expect(bad).toMatchObject({ isError: true, json: { code: 'INVALID_PARAMETER' } });
  const far = await callTool(client, 'move_forward', { distanceCm: 900 });
  expect(far).toMatchObject({ isError: true, json: { code: 'RANGE_EXCEEDED' } });
  const unknown = await callTool(client, 'teleport', {});
  expect(unknown).toMatchObject({ isError: true, json: { code: 'UNKNOWN_TOOL' } });
  const still = await callTool(client, 'get_pose');
  expect((still.json['position'] as { x: number }).x).toBeCloseTo(0.2, 2);

  const estop = await callTool(client, 'emergency_stop', { reason: 'test' });
  expect(estop.isError, estop.text).toBe(false);
  const refused = await callTool(client, 'move_forward', { distanceCm: 5 });
  expect(refused).toMatchObject({ isError: true, json: { code: 'EMERGENCY_STOPPED' } });
  const state = await client.readResource({ uri: 'robot://state' });
  const stateText = (state.contents[0] as { text: string }).text;
  expect(JSON.parse(stateText)).toMatchObject({ ready: true, safety: { emergencyStopped: true } });
  expect((await callTool(client, 'reset_emergency_stop')).isError).toBe(false);
}
