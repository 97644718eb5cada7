import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PassThrough } from 'node:stream';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StreamableHTTPClientTransport } from '@modelcontextprotocol/sdk/client/streamableHttp.js';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';
import { waitForOutput } from '../wait-output.fixture.js';

let dir = '';
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-mcp-cli-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

/** A world with a red box 1.2 m straight ahead of the robot (its near face 1.05 m away). */
const RED_BOX_AHEAD = {
  map: 'empty',
  start: { x: 0, y: 0, yawDeg: 0 },
  objects: [{ name: 'red-box', kind: 'box', colour: 'red', x: 1.2, y: 0 }],
};

/** Serves `args` over HTTP in-process; `use` gets an SDK client connected to it. */
async function withServer(
  args: string[],
  use: (client: Client, stderr: () => string) => Promise<void>,
): Promise<void> {
  const io = captureIO({});
  const serving = runHal(['mcp', '--http', '--port', '0', ...args], io);
  await waitForOutput(io, (o) => /MCP over HTTP at (\S+)/.test(o.stderr()));
  const url = /MCP over HTTP at (\S+)/.exec(io.stderr())![1]!;
  const client = new Client({ name: 'hal-mcp-test', version: '1.0.0' });
  await client.connect(new StreamableHTTPClientTransport(new URL(url)));
  try {
    await use(client, () => io.stderr());
  } finally {
    await client.close();
    io.abort();
    expect(await serving, io.stderr()).toBe(0);
  }
  expect(io.stdout()).toBe('');
}

/** A tool call's text, facts (structuredContent) and isError. */
async function call(client: Client, name: string, args: Record<string, unknown> = {}) {
  const result = await client.callTool({ name, arguments: args });
  const content = result.content as Array<{ type: string; text?: string }>;
  return {
    isError: result.isError === true,
    text: content.find((c) => c.type === 'text')?.text ?? '',
    facts: (result.structuredContent ?? {}) as Record<string, unknown>,
  };
}

/** The simulated robot's pose, as the robot://state resource reads it. */
async function poseOf(client: Client): Promise<{ x: number; y: number }> {
  const state = await client.readResource({ uri: 'robot://state' });
  const text = (state.contents[0] as { text: string }).text;
  return (JSON.parse(text) as { pose: { position: { x: number; y: number } } }).pose.position;
}

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

  it('offers the skills with --tools skills: move and go_to drive the simulator, refusals are errors', async () => {
    const world = join(dir, 'red-box.json');
    await writeFile(world, JSON.stringify(RED_BOX_AHEAD));
    // the fence keeps the robot from backing out past x = -0.3
    const args = ['--tools', 'skills', '--world', world, '--time-scale', '10'];
    await withServer([...args, '--geofence', '-0.3,3,-1,1'], async (client, stderr) => {
      expect(stderr()).toContain('hal mcp: simulation robot, skills tools, MCP over HTTP at');
      const names = (await client.listTools()).tools.map((tool) => tool.name);
      expect(names).toEqual(
        expect.arrayContaining(['look', 'find', 'go_to', 'move', 'turn', 'go_back']),
      );
      expect(names.slice(-3)).toEqual(['stop', 'emergency_stop', 'reset_emergency_stop']);
      expect(names).not.toContain('move_forward');

      const moved = await call(client, 'move', { cm: 20 });
      expect(moved, moved.text).toMatchObject({
        isError: false,
        text: expect.stringMatching(/^Moved 20\.\d cm forward\./),
        facts: { outcome: 'done' },
      });
      expect(Math.abs((moved.facts['movedCm'] as number) - 20)).toBeLessThan(0.5);
      expect((await poseOf(client)).x).toBeCloseTo(0.2, 2);

      // the leash refuses: nothing moves, and the result is an error the model can read
      const refused = await call(client, 'move', { cm: -100 });
      expect(refused).toMatchObject({
        isError: true,
        text: expect.stringMatching(/^Refused, nothing moved/),
        facts: { outcome: 'refused', code: expect.stringMatching(/^LEASH_/) },
      });
      expect((await poseOf(client)).x).toBeCloseTo(0.2, 2);

      const reached = await call(client, 'go_to', { target: 'red box' });
      expect(reached, reached.text).toMatchObject({
        isError: false,
        text: expect.stringMatching(/^Reached the red box/),
        facts: { outcome: 'reached' },
      });
      // the robot is short of the box's near face (x 1.05), nearer than it began
      const { x } = await poseOf(client);
      expect(x).toBeGreaterThan(0.6);
      expect(x).toBeLessThan(1.05);

      // a tool of another profile is an error too; resources name the offered tools
      const unknown = await call(client, 'move_forward', { distanceCm: 10 });
      expect(unknown).toMatchObject({ isError: true, facts: { code: 'UNKNOWN_TOOL' } });
      const caps = await client.readResource({ uri: 'robot://capabilities' });
      const listed = JSON.parse((caps.contents[0] as { text: string }).text) as { tools: string[] };
      expect(listed.tools).toEqual(names);

      const estop = await call(client, 'emergency_stop', { reason: 'test' });
      expect(estop.isError).toBe(false);
      const stopped = await call(client, 'move', { cm: 10 });
      expect(stopped).toMatchObject({
        isError: true,
        facts: { outcome: 'estopped', code: 'EMERGENCY_STOPPED' },
      });
      expect((await call(client, 'reset_emergency_stop')).isError).toBe(false);
    });
  }, 120_000);

  it('offers both with --tools all, the HAL tools alone by default, and says when the skills cannot see', async () => {
    await withServer(['--tools', 'all'], async (client) => {
      const names = (await client.listTools()).tools.map((tool) => tool.name);
      expect(names).toEqual(expect.arrayContaining(['go_to', 'look', 'move_forward', 'get_pose']));
      const pose = await call(client, 'get_pose');
      expect(pose.isError).toBe(false);
      // a HAL tool's facts are the JSON its text carries
      expect(pose.facts).toEqual(JSON.parse(pose.text));
    });
    // a robot with no camera: said once on stderr; a skill that looks answers an error
    const blind = join(dir, 'no-camera.json');
    await writeFile(blind, JSON.stringify({ ...RED_BOX_AHEAD, sensors: { camera: false } }));
    await withServer(['--tools', 'skills', '--world', blind], async (client, stderr) => {
      expect(stderr()).toContain('hal mcp: the robot has no camera: the skills that look');
      expect(await call(client, 'look')).toMatchObject({ isError: true });
    });
    await withServer([], async (client, stderr) => {
      expect(stderr()).toContain('primitives tools');
      expect(stderr()).not.toContain('no camera');
      const names = (await client.listTools()).tools.map((tool) => tool.name);
      expect(names).toContain('move_forward');
      expect(names).not.toContain('go_to');
    });
  }, 60_000);

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
      ['mcp', '--world', join(dir, 'none.json')],
    ]) {
      expect(await runHal(argv, captureIO({})), argv.join(' ')).toBe(2);
    }
    const profile = captureIO({});
    expect(await runHal(['mcp', '--http', '--port', '0', '--tools', 'tiny'], profile)).toBe(2);
    expect(profile.stderr()).toContain(
      'hal: USAGE: "--tools" must be one of skills, primitives, all, got "tiny"',
    );
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
