// `hal mcp --foxglove 0` as an MCP client starts it: the client drives the robot over stdio while
// a Foxglove viewer (the `@foxglove/ws-protocol` client) watches it move, and the protocol's
// stdout carries nothing of the live view.
import type { Stream } from 'node:stream';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { describe, expect, it } from 'vitest';
import { callTool, serverCommand } from '../mcp/client.js';
import { connectViewer } from './viewer.js';

/** Resolves with the first line of `stream` that `pattern` matches (at most 30 s). */
function lineOf(stream: Stream, pattern: RegExp): Promise<RegExpMatchArray> {
  return new Promise((resolve, reject) => {
    let text = '';
    const timer = setTimeout(
      () => reject(new Error(`no line like ${pattern} within 30 s; stderr: ${text}`)),
      30_000,
    );
    stream.on('data', (chunk: Buffer) => {
      text += chunk.toString();
      const match = pattern.exec(text);
      if (match !== null) {
        clearTimeout(timer);
        resolve(match);
      }
    });
  });
}

describe('hal mcp --foxglove', () => {
  it('lets a Foxglove viewer watch the robot the MCP client drives', async () => {
    const transport = new StdioClientTransport({
      ...serverCommand(['--foxglove', '0']),
      stderr: 'pipe',
    });
    const stderr = transport.stderr;
    if (stderr === null) throw new Error('no stderr to read');
    const announced = lineOf(stderr, /live view for Foxglove or Lichtblick: open (ws:\/\/\S+)/);
    const client = new Client({ name: 'hal-test', version: '1.0.0' });
    await client.connect(transport);
    try {
      const url = (await announced)[1]!;
      expect(url).toMatch(/^ws:\/\/127\.0\.0\.1:\d+$/);
      const viewer = await connectViewer(url);
      try {
        await viewer.subscribe('/hal/pose');
        await viewer.until(() => viewer.on('/hal/pose').length >= 1);
        const x = () =>
          (viewer.on('/hal/pose').at(-1)!.value['pose'] as { position: { x: number } }).position.x;
        const before = x();
        const moved = await callTool(client, 'move_forward', { distanceCm: 20 });
        expect(moved.isError, moved.text).toBe(false);
        // poses published after the motion ended: one in flight may be from before its end
        const returned = viewer.on('/hal/pose').length;
        await viewer.until(() => viewer.on('/hal/pose').length >= returned + 3);
        expect(x() - before).toBeCloseTo(0.2, 2);
      } finally {
        viewer.close();
      }
    } finally {
      await client.close();
    }
  }, 60_000);
});
