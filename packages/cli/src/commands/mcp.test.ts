import { createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { PassThrough } from 'node:stream';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StreamableHTTPClientTransport } from '@modelcontextprotocol/sdk/client/streamableHttp.js';
import { describe, expect, it } from 'vitest';
import { captureIO } from '../capture-io.fixture.js';
import { runHal } from '../program.js';
import { waitForOutput } from '../wait-output.fixture.js';

describe('hal mcp', () => {
  it('serves the simulator over HTTP until stopped, to the SDK client, its messages on stderr', async () => {
    const io = captureIO({});
    const serving = runHal(['mcp', '--http', '--port', '0', '--max-distance', '0.5'], io);
    await waitForOutput(io, (o) => /MCP over HTTP at (\S+)/.test(o.stderr()));
    const url = /MCP over HTTP at (\S+)/.exec(io.stderr())![1]!;
    expect(io.stderr()).toContain('hal mcp: simulation robot');
    expect(url).toMatch(/^http:\/\/127\.0\.0\.1:\d+\/mcp$/);

    const client = new Client({ name: 'hal-mcp-test', version: '1.0.0' });
    await client.connect(new StreamableHTTPClientTransport(new URL(url)));
    try {
      const names = (await client.listTools()).tools.map((tool) => tool.name);
      expect(names).toEqual(expect.arrayContaining(['move_forward', 'emergency_stop']));
      // the leash of the command line holds: 1 m is beyond --max-distance 0.5
      const refused = await client.callTool({
        name: 'move_forward',
        arguments: { distanceCm: 100 },
      });
      expect(refused.isError).toBe(true);
    } finally {
      await client.close();
    }
    io.abort();
    expect(await serving).toBe(0);
    // nothing but the protocol may go to stdout
    expect(io.stdout()).toBe('');
  }, 30_000);

  it('answers over stdio and stops when the client closes its input', async () => {
    const stdin = new PassThrough();
    const io = { ...captureIO({}), stdin };
    const serving = runHal(['mcp'], io);
    await waitForOutput(io, (o) => o.stderr().includes('MCP over stdio'));
    stdin.write(
      `${JSON.stringify({
        jsonrpc: '2.0',
        id: 1,
        method: 'initialize',
        params: {
          protocolVersion: '2025-03-26',
          capabilities: {},
          clientInfo: { name: 'test', version: '1' },
        },
      })}\n`,
    );
    await waitForOutput(io, (o) => o.stdout().includes('"id":1'));
    expect(JSON.parse(io.stdout().split('\n')[0]!)).toMatchObject({
      id: 1,
      result: { serverInfo: { name: expect.any(String) } },
    });
    stdin.end();
    expect(await serving).toBe(0);
  }, 30_000);

  it('refuses bad options with a usage error, and HTTP beyond loopback without a token', async () => {
    for (const argv of [
      ['mcp', '--geofence', '1,0,0,1'],
      ['mcp', '--map', 'moon'],
      ['mcp', '--port', 'x'],
      ['mcp', '--http', '--port', '99999'],
      ['mcp', '--udp', 'x', '--ws', 'ws://127.0.0.1:1'],
    ]) {
      expect(await runHal(argv, captureIO({})), argv.join(' ')).toBe(2);
    }
    // no standard input to speak over (the in-process runs above have none either)
    const noStdin = captureIO({});
    expect(await runHal(['mcp'], noStdin)).toBe(2);
    expect(noStdin.stderr()).toContain('MCP over stdio needs a standard input');
    const open = captureIO({});
    expect(await runHal(['mcp', '--http', '--host', '0.0.0.0', '--port', '0'], open)).toBe(2);
    expect(open.stderr()).toMatch(
      /hal: USAGE: "--host" 0\.0\.0\.0 is reachable from other machines: give --http-token/,
    );
  }, 30_000);

  it('says which option changes a port in use', async () => {
    const taken = createServer();
    await new Promise<void>((resolve) => taken.listen(0, '127.0.0.1', resolve));
    const { port } = taken.address() as AddressInfo;
    try {
      const io = captureIO({});
      expect(await runHal(['mcp', '--http', '--port', String(port)], io)).toBe(1);
      expect(io.stderr()).toContain(
        `hal: FAILED: port ${port} is in use (EADDRINUSE); choose another with --port`,
      );
    } finally {
      await new Promise((resolve) => taken.close(resolve));
    }
  }, 30_000);
});
