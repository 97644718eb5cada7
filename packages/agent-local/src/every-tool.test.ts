// The local provider given every tool: the real SmolLM2-135M model (which `hal model pull`
// caches) with no `offerTools`, so the grammar holds every tool of @hal/tools' catalog (17 on the
// simulator, more with a speaker and an arm), and a real generation under it. Loaded once for the
// file, on one thread. What the small model chooses is not asserted, only that its reply is
// one of the offered calls or an answer.
import { runAgent } from '@hal/agent';
import type { AgentEvent } from '@hal/agent';
import { SimulationHAL, World } from '@hal/simulation';
import { createToolExecutor, halTools, TOOL_CATALOG } from '@hal/tools';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { everyChatTool } from './every-tool.fixture.js';
import { createLocalChatProvider } from './local-provider.js';
import type { LocalChatProvider } from './local-provider.js';

const MODEL_MS = 180_000; // a shared, busy CPU can be slow; a quiet one takes a few seconds

let provider: LocalChatProvider;
let hal: SimulationHAL;
beforeAll(async () => {
  provider = await createLocalChatProvider({ threads: 1, gpu: false, maxTokens: 64 });
  hal = new SimulationHAL({ world: new World({ map: 'empty' }) });
  await hal.initialize();
}, MODEL_MS);
afterAll(async () => {
  await provider?.dispose();
  await hal?.cleanup();
});

describe('the local provider with every tool', () => {
  it(
    'builds the grammar of the whole catalog',
    async () => {
      const tools = everyChatTool();
      expect(tools).toHaveLength(TOOL_CATALOG.length);
      await expect(provider.prepare(tools)).resolves.toBeUndefined();
    },
    MODEL_MS,
  );

  it(
    "runs a generation offered every tool the simulator's robot has; the reply is one of them or an answer",
    async () => {
      const tools = halTools(hal);
      expect(tools.map((t) => t.name)).toContain('log');
      const events: AgentEvent[] = [];
      const outcome = await runAgent({
        goal: 'drive forward 10 cm',
        executor: createToolExecutor(hal, { tools }),
        provider,
        caps: { maxSteps: 1 },
        onEvent: (event) => events.push(event),
      });
      expect(outcome.error, outcome.error?.message).toBeUndefined();
      expect(['completed', 'max_steps']).toContain(outcome.reason);
      const streamed = events.flatMap((e) => (e.type === 'token' ? [e.text] : [])).join('');
      const reply = JSON.parse(streamed) as { tool?: string; answer?: string };
      if (reply.tool !== undefined) expect(tools.map((t) => t.name)).toContain(reply.tool);
      else expect(typeof reply.answer).toBe('string');
    },
    MODEL_MS,
  );
});
