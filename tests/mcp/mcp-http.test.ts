import { request } from 'node:http';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StreamableHTTPClientTransport } from '@modelcontextprotocol/sdk/client/streamableHttp.js';
import { createRobotMcpServer, serveHttp } from '@hal/mcp';
import type { HttpEndpoint } from '@hal/mcp';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor } from '@hal/tools';
import { afterEach, describe, expect, it } from 'vitest';
import { driveOverMcp } from './scenario.js';

const open: Array<{ close(): Promise<void> }> = [];
afterEach(async () => {
  for (const thing of open.splice(0).reverse()) await thing.close();
});

async function serve(
  options: { token?: string } = {},
): Promise<{ endpoint: HttpEndpoint; hal: SimulationHAL }> {
  const hal = new SimulationHAL();
  await hal.initialize();
  const executor = createToolExecutor(hal);
  const endpoint = await serveHttp(
    () => createRobotMcpServer(hal, executor, { map: () => hal.world.map }),
    {
      port: 0,
      ...options,
    },
  );
  open.push(endpoint, { close: () => hal.cleanup() });
  return { endpoint, hal };
}

async function connect(url: string, token?: string): Promise<Client> {
  const client = new Client({ name: 'hal-test', version: '1.0.0' });
  const headers: Record<string, string> =
    token === undefined ? {} : { authorization: `Bearer ${token}` };
  await client.connect(
    new StreamableHTTPClientTransport(new URL(url), { requestInit: { headers } }),
  );
  open.push(client);
  return client;
}

/** POSTs an empty JSON-RPC body with chosen headers (fetch may not set Host); answers the status. */
function post(url: string, headers: Record<string, string>): Promise<number> {
  return new Promise((resolve, reject) => {
    const req = request(
      url,
      {
        method: 'POST',
        headers: {
          'content-type': 'application/json',
          accept: 'application/json, text/event-stream',
          ...headers,
        },
        timeout: 10_000,
      },
      (res) => {
        res.resume();
        resolve(res.statusCode ?? 0);
      },
    );
    req.on('error', reject);
    req.on('timeout', () => req.destroy(new Error('no answer')));
    req.end('{}');
  });
}

describe('hal mcp over streamable HTTP on 127.0.0.1 (the SDK client)', () => {
  it('lists the tools, moves, reads the pose, gets a frame, refuses bad arguments and e-stops', async () => {
    const { endpoint, hal } = await serve();
    expect(endpoint.url).toMatch(/^http:\/\/127\.0\.0\.1:\d+\/mcp$/);
    await driveOverMcp(await connect(endpoint.url));
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.2, 2);
  });

  it('answers requests without the token 401, and serves those with it', async () => {
    const token = 'a-long-enough-test-token';
    const { endpoint } = await serve({ token });
    await expect(connect(endpoint.url)).rejects.toThrow(/401|bearer token/i);
    await expect(connect(endpoint.url, 'wrong-token-of-the-same-size!!')).rejects.toThrow(
      /401|bearer token/i,
    );
    const client = await connect(endpoint.url, token);
    expect((await client.listTools()).tools.length).toBeGreaterThan(5);
  });

  it('refuses a Host that is not loopback when it has no token (DNS rebinding)', async () => {
    const { endpoint } = await serve();
    expect(await post(endpoint.url, { host: 'evil.example' })).toBe(403);
    expect(await post(endpoint.url, { origin: 'http://evil.example' })).toBe(403);
    expect(await post(endpoint.url, { host: `127.0.0.1:${endpoint.port}` })).not.toBe(403);
  });

  it('refuses to listen on another address than loopback without a token', async () => {
    const hal = new SimulationHAL();
    const create = () => createRobotMcpServer(hal, createToolExecutor(hal));
    await expect(serveHttp(create, { host: '0.0.0.0', port: 0 })).rejects.toThrow(/needs --token/);
    await expect(serveHttp(create, { host: '0.0.0.0', port: 0, token: 'short' })).rejects.toThrow(
      /at least 16/,
    );
  });
});
