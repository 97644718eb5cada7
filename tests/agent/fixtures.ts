// Shared by the agent loop tests: a fake endpoint per test, a recorder of the run's events, and
// a tiny executor that implements the @hal/tools executor types without a robot.
import type { AgentEvent, AgentToolExecutor } from '@hal/agent';
import type { HalTool, ToolCall, ToolResult } from '@hal/tools';
import { afterEach } from 'vitest';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import type { FakeOpenAIServer, ScriptedReply } from '../helpers/fake-openai-server.js';

let current: FakeOpenAIServer | undefined;
afterEach(async () => {
  await current?.close();
  current = undefined;
});

/** Starts the fake endpoint for this test (closed after it). */
export async function serve(script: ScriptedReply[]): Promise<FakeOpenAIServer> {
  current = await startFakeOpenAIServer(script);
  return current;
}

/** The events of a run, and a listener that records them. */
export function recorder(): { events: AgentEvent[]; onEvent: (e: AgentEvent) => void } {
  const events: AgentEvent[] = [];
  return { events, onEvent: (e) => events.push(e) };
}

/** A tool call in a scripted reply, its arguments as JSON. */
export function call(name: string, args: Record<string, unknown> = {}) {
  return { name, arguments: JSON.stringify(args) };
}

function tool(name: string, safety?: 'stop'): HalTool {
  return {
    name,
    call: name === 'stop' ? 'stop' : 'getPose',
    description: `fake ${name}`,
    inputSchema: { type: 'object', properties: {} },
    motion: name !== 'get_pose',
    ...(safety === undefined ? {} : { safety }),
  } as HalTool;
}

/** An executor with `get_pose`, `wait` (which takes `waitMs` to answer) and `stop`; it records calls. */
export function fakeExecutor(waitMs = 0): AgentToolExecutor & { calls: ToolCall[] } {
  const calls: ToolCall[] = [];
  return {
    calls,
    tools: [tool('get_pose'), tool('wait'), tool('stop', 'stop')],
    async execute(c: ToolCall): Promise<ToolResult> {
      calls.push(c);
      if (c.name === 'wait') await new Promise((resolve) => setTimeout(resolve, waitMs));
      const text = JSON.stringify({ ok: c.name });
      return { isError: false, content: [{ type: 'text', text }] };
    },
  };
}

export const endpoint = (s: FakeOpenAIServer) => ({
  baseUrl: s.baseUrl,
  model: 'test-tool-model',
  apiKey: 'sk-test',
});
