// docs/mcp.md's client configuration for a checkout, used as a client uses it: the `command`,
// `args` and `cwd` of its first `mcpServers` entry (with the repository's real path for
// /path/to/repo) start the server, which answers over stdio.
import { readFileSync } from 'node:fs';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { fencedBlocks } from '@hal/types/testing';
import { describe, expect, it } from 'vitest';
import { callTool, REPO_ROOT } from './client.js';

interface ClientConfig {
  mcpServers: Record<string, { command: string; args: string[]; cwd?: string }>;
}
const root = REPO_ROOT.replace(/\/$/, '');
// the JSON blocks that configure a client (others show what a resource holds)
const configs = fencedBlocks(readFileSync(`${root}/docs/mcp.md`, 'utf8'), 'json')
  .map((text) => JSON.parse(text.replaceAll('/path/to/repo', root)) as Partial<ClientConfig>)
  .filter((json): json is ClientConfig => json.mcpServers !== undefined);

describe("docs/mcp.md's MCP client configurations", () => {
  it('show the checkout first, the packed tarballs next, and npx only as the published form', () => {
    const commands = configs.map((c) => Object.values(c.mcpServers)[0]?.command);
    expect(commands).toEqual(['node', '/path/to/robot-app/node_modules/.bin/hal', 'npx']);
  });

  it('start a server from a checkout that lists the tools and drives the simulator', async () => {
    const entry = Object.values(configs[0]!.mcpServers)[0]!;
    const client = new Client({ name: 'hal-docs-test', version: '1.0.0' });
    await client.connect(
      new StdioClientTransport({
        command: entry.command === 'node' ? process.execPath : entry.command,
        args: entry.args,
        ...(entry.cwd === undefined ? {} : { cwd: entry.cwd }),
        stderr: 'ignore',
      }),
    );
    try {
      const names = (await client.listTools()).tools.map((t) => t.name);
      expect(names).toEqual(expect.arrayContaining(['move_forward', 'get_pose']));
      const moved = await callTool(client, 'move_forward', { distanceCm: 5 });
      expect(moved.isError, moved.text).toBe(false);
    } finally {
      await client.close();
    }
  });
});
