// `hal mcp --record FILE`: the MCP server as its own process, driven by the SDK's client over
// stdio; the robot's run (the HAL calls the tools made, the pose, the e-stop) is in the file once
// the client has gone and the server has stopped the robot.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { readRecordingFile, summarizeRecording, TOPICS } from '@hal/recorder';
import type { HalCallRecord, SafetyEvent } from '@hal/recorder';
import { afterAll, describe, expect, it } from 'vitest';
import { callTool, serverCommand } from '../mcp/client.js';
import { expectWellFormed } from './well-formed.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-mcp-record-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

describe('hal mcp --record', () => {
  it("records the robot's calls, pose and e-stop made through the MCP tools, and says so on stderr", async () => {
    const file = join(dir, 'mcp.mcap');
    const transport = new StdioClientTransport({
      ...serverCommand(['--record', file]),
      stderr: 'pipe',
    });
    let stderr = '';
    transport.stderr?.on('data', (chunk: Buffer) => (stderr += chunk.toString()));
    const client = new Client({ name: 'hal-record-test', version: '1.0.0' });
    await client.connect(transport);
    try {
      expect((await callTool(client, 'move_forward', { distanceCm: 10 })).isError).toBe(false);
      expect((await callTool(client, 'rotate', { direction: 'left', degrees: 90 })).isError).toBe(
        false,
      );
      expect((await callTool(client, 'move_forward', { distanceCm: Number.NaN })).isError).toBe(
        true,
      );
      expect((await callTool(client, 'emergency_stop', { reason: 'mcp operator' })).isError).toBe(
        false,
      );
    } finally {
      await client.close(); // ends the server's stdin: it stops the robot and closes the file
    }
    expect(stderr).toMatch(/hal mcp: recorded \d+ messages to .*mcp\.mcap/);

    const recording = await readRecordingFile(file);
    expect(recording.complete).toBe(true);
    expectWellFormed(recording);
    expect(recording.metadata.get('hal.robot')).toMatchObject({
      mode: 'simulation',
      map: '{"name":"empty"}',
    });
    const calls = recording.messages
      .filter((m) => m.topic === TOPICS.calls)
      .map((m) => m.value as HalCallRecord);
    const moves = calls.filter(
      (c) => c.call.startsWith('locomotion.') && c.call !== 'locomotion.getPose',
    );
    expect(moves.map((c) => [c.call, c.success])).toEqual([
      ['locomotion.moveForward', true],
      ['locomotion.rotate', true],
    ]);
    expect(calls.at(-1)?.call).toBe('cleanup');
    const safety = recording.messages
      .filter((m) => m.topic === TOPICS.safety)
      .map((m) => m.value as SafetyEvent);
    expect(safety[0]).toMatchObject({
      event: 'emergency_stop',
      reason: 'mcp operator',
      success: true,
    });
    // after 10 cm ahead and a left turn the robot stands at (0.1, 0) facing +y
    const pose = recording.messages.filter((m) => m.topic === TOPICS.halPose).at(-1)?.value as {
      position: { x: number };
      rotation: { yaw: number };
    };
    expect(pose.position.x).toBeCloseTo(0.1, 3);
    expect(pose.rotation.yaw).toBeCloseTo(Math.PI / 2, 2);
    expect(summarizeRecording(recording)).toMatchObject({ emergencyStops: 1, dropped: 0 });
  }, 60_000);

  it('refuses a file it cannot write before the robot is touched', async () => {
    const transport = new StdioClientTransport({
      ...serverCommand(['--record', join(dir, 'no-such-dir', 'x.mcap')]),
      stderr: 'pipe',
    });
    let stderr = '';
    transport.stderr?.on('data', (chunk: Buffer) => (stderr += chunk.toString()));
    const client = new Client({ name: 'hal-record-test', version: '1.0.0' });
    await expect(client.connect(transport)).rejects.toThrow();
    await client.close().catch(() => undefined);
    expect(stderr).toContain(
      `hal: USAGE: "--record" ${join(dir, 'no-such-dir', 'x.mcap')}: its folder ${join(dir, 'no-such-dir')} does not exist`,
    );
  }, 30_000);
});
