// The server over any tool set, with the SDK's own client over an in-memory pair: it lists the
// tools it is given, runs calls through them, hands back each result's facts as
// structuredContent and its refusals as isError, and names the tools in robot://capabilities.
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { InMemoryTransport } from '@modelcontextprotocol/sdk/inMemory.js';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor, errorResult } from '@hal/tools';
import type { AgentTool, ToolCall, ToolResult } from '@hal/tools';
import { afterEach, describe, expect, it } from 'vitest';
import { createRobotMcpServer } from './server.js';
import type { OfferedTools } from './server.js';

let sim: SimulationHAL | undefined;
let client: Client | undefined;
afterEach(async () => {
  await client?.close();
  await sim?.cleanup();
  client = undefined;
  sim = undefined;
});

async function connect(offered: (hal: SimulationHAL) => OfferedTools): Promise<Client> {
  sim = new SimulationHAL();
  await sim.initialize();
  const server = createRobotMcpServer(sim, offered(sim));
  const [clientSide, serverSide] = InMemoryTransport.createLinkedPair();
  await server.connect(serverSide);
  client = new Client({ name: 'hal-mcp-server-test', version: '1.0.0' });
  await client.connect(clientSide);
  return client;
}

/** One tool that is no HAL call: it answers a sentence and its facts, or refuses. */
const WAVE: AgentTool = {
  name: 'wave',
  description: 'Waves, times times.',
  inputSchema: {
    type: 'object',
    properties: { times: { type: 'number' } },
    required: ['times'],
  },
  motion: false,
};

function waving(): OfferedTools & { calls: ToolCall[] } {
  const calls: ToolCall[] = [];
  return {
    calls,
    tools: [WAVE],
    execute: async (call): Promise<ToolResult> => {
      calls.push(call);
      if (call.name !== 'wave') return errorResult('UNKNOWN_TOOL', `no tool "${call.name}"`);
      const times = (call.arguments as { times: number }).times;
      if (times > 3) return errorResult('LEASH_WAVES', 'at most 3 waves');
      return {
        isError: false,
        content: [{ type: 'text', text: `Waved ${times} times.` }],
        structured: { outcome: 'done', waved: times },
      };
    },
  };
}

describe('createRobotMcpServer', () => {
  it('offers the tools it is given, their facts as structuredContent, refusals as errors', async () => {
    const offered = waving();
    const c = await connect(() => offered);
    expect((await c.listTools()).tools.map((t) => t.name)).toEqual(['wave']);

    const waved = await c.callTool({ name: 'wave', arguments: { times: 2 } });
    expect(waved).toMatchObject({
      isError: false,
      content: [{ type: 'text', text: 'Waved 2 times.' }],
      structuredContent: { outcome: 'done', waved: 2 },
    });
    expect(offered.calls).toEqual([{ name: 'wave', arguments: { times: 2 } }]);

    const refused = await c.callTool({ name: 'wave', arguments: { times: 9 } });
    expect(refused).toMatchObject({
      isError: true,
      structuredContent: { code: 'LEASH_WAVES', error: 'at most 3 waves' },
    });
    const unknown = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 10 } });
    expect(unknown).toMatchObject({ isError: true, structuredContent: { code: 'UNKNOWN_TOOL' } });

    // the resources name the tools offered, not the HAL's
    const caps = await c.readResource({ uri: 'robot://capabilities' });
    const text = (caps.contents[0] as { text: string }).text;
    expect((JSON.parse(text) as { tools: string[] }).tools).toEqual(['wave']);
  });

  it("gives a HAL tool's JSON text back as its structuredContent too", async () => {
    const c = await connect((hal) => createToolExecutor(hal));
    const moved = await c.callTool({ name: 'move_forward', arguments: { distanceCm: 10 } });
    const content = moved.content as Array<{ type: string; text: string }>;
    expect(moved.isError).toBe(false);
    expect(moved.structuredContent).toEqual(JSON.parse(content[0]?.text ?? ''));
    expect(moved.structuredContent).toMatchObject({ success: true });
  });
});
