// The real thing: SmolLM2-135M (from `hal model pull`) on the CPU, driving SimulationHAL.
// Loaded once for the file, on one thread (other test files share the cores); each run is a few
// dozen tokens. Nothing here asserts that the small model chose well: only what the code
// guarantees.
import { mkdtemp, open, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runAgent } from '@hal/agent';
import type { AgentEvent, AgentToolExecutor } from '@hal/agent';
import { createToolExecutor, toOpenAITools } from '@hal/tools';
import type { HalTool } from '@hal/tools';
import { SimulationHAL, World } from '@hal/simulation';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { createLocalChatProvider } from './local-provider.js';
import type { LocalChatProvider } from './local-provider.js';
import { defaultModelFile } from './model-file.js';
import { LOCAL_SYSTEM_PROMPT, SMALL_MODEL_TOOLS } from './prompt.js';

const MODEL_MS = 120_000; // a shared, busy CPU can be slow; a quiet one takes a few seconds

let provider: LocalChatProvider;
let hal: SimulationHAL;

beforeAll(async () => {
  // a missing model fails here, with the message that names hal model pull
  provider = await createLocalChatProvider({
    threads: 1,
    gpu: false,
    offerTools: SMALL_MODEL_TOOLS,
    maxTokens: 48,
  });
  hal = new SimulationHAL({ world: new World({ map: 'empty' }) });
  await hal.initialize();
}, MODEL_MS);

afterAll(async () => {
  await provider?.dispose();
  await hal?.cleanup();
});

function recorder() {
  const events: AgentEvent[] = [];
  return { events, onEvent: (event: AgentEvent) => events.push(event) };
}

describe('createLocalChatProvider', () => {
  it(
    'runs a real generation whose tool call parses, validates and runs on the simulator, and the run ends',
    async () => {
      const { events, onEvent } = recorder();
      const outcome = await runAgent({
        goal: 'drive forward 10 cm',
        hal,
        provider,
        systemPrompt: LOCAL_SYSTEM_PROMPT,
        caps: { maxSteps: 1 },
        onEvent,
      });
      expect(['completed', 'max_steps']).toContain(outcome.reason);
      expect(events.at(-1)).toMatchObject({ type: 'done', reason: outcome.reason });
      const usage = events.find((e) => e.type === 'usage');
      expect(usage).toMatchObject({ step: 1 });
      expect(usage?.type === 'usage' && usage.completionTokens).toBeGreaterThan(0);
      const streamed = events.flatMap((e) => (e.type === 'token' ? [e.text] : [])).join('');
      const call = events.find((e) => e.type === 'tool_call' && e.step === 1);
      if (outcome.reason === 'completed') {
        // the model answered in words: that is the whole reply
        expect(outcome.text.length).toBeGreaterThan(0);
        return;
      }
      expect(call?.type).toBe('tool_call');
      if (call?.type !== 'tool_call') return;
      // the streamed text is the call, as JSON in the grammar's shape
      expect(JSON.parse(streamed)).toEqual({
        tool: call.name,
        arguments: JSON.parse(call.arguments),
      });
      expect(SMALL_MODEL_TOOLS).toContain(call.name);
      const result = events.find((e) => e.type === 'tool_result' && e.id === call.id);
      expect(result?.type).toBe('tool_result');
      // arguments always reach the robot's own validation: never malformed or unknown
      if (result?.type === 'tool_result' && result.isError)
        expect(['BAD_ARGUMENTS', 'UNKNOWN_TOOL']).not.toContain(result.code);
    },
    MODEL_MS,
  );

  it(
    'stops generating when the run is aborted mid-reply, and stops the robot',
    async () => {
      const controller = new AbortController();
      const { events, onEvent } = recorder();
      // a motion under way when the run starts: the abort must end it
      const moving = await hal.locomotion.drive(120, 120, 60_000);
      expect(moving.success).toBe(true);
      const outcome = await runAgent({
        goal: 'drive backward 20 cm',
        hal,
        provider,
        systemPrompt: LOCAL_SYSTEM_PROMPT,
        signal: controller.signal,
        onEvent: (event) => {
          onEvent(event);
          if (event.type === 'token') controller.abort();
        },
      });
      expect(outcome.reason).toBe('aborted');
      const tokens = events.filter((e) => e.type === 'token').length;
      // generation stopped at the first token: no reply, so no tool call from the model
      expect(tokens).toBeLessThanOrEqual(2);
      expect(
        events.filter((e) => e.type === 'tool_call').map((e) => e.type === 'tool_call' && e.name),
      ).toEqual(['stop']);
      const pose = await hal.locomotion.getPose();
      expect(pose.velocity.linear).toBe(0);
      // and the model is free for the next run
      await expect(
        provider.complete(
          {
            messages: [
              { role: 'system', content: 'x' },
              { role: 'user', content: 'hi' },
            ],
            tools: [],
          },
          {
            step: 1,
            signal: AbortSignal.abort(),
            onRetry: () => undefined,
            onToken: () => undefined,
            onContextTrimmed: () => undefined,
          },
        ),
      ).rejects.toBeDefined();
    },
    MODEL_MS,
  );

  it('refuses a tool whose schema the grammar cannot express, naming the tool', async () => {
    const base = createToolExecutor(hal);
    // get_pose (one of the offered tools) given a schema with a regular expression
    const tools: HalTool[] = base.tools.map((tool) =>
      tool.name === 'get_pose'
        ? {
            ...tool,
            inputSchema: {
              type: 'object',
              properties: { frame: { type: 'string', pattern: '^[a-z]+$' } },
            },
          }
        : tool,
    );
    const executor: AgentToolExecutor = { tools, execute: (call) => base.execute(call) };
    await expect(provider.prepare(toOpenAITools(tools))).rejects.toMatchObject({
      code: 'SCHEMA_UNSUPPORTED',
      message: expect.stringContaining('tool "get_pose"'),
    });
    const { events, onEvent } = recorder();
    const outcome = await runAgent({ goal: 'where are you?', executor, provider, onEvent });
    expect(outcome.reason).toBe('error');
    expect(outcome.error?.code).toBe('PROVIDER');
    expect(outcome.error?.details).toEqual({ code: 'SCHEMA_UNSUPPORTED' });
    expect(outcome.error?.message).toContain('tool "get_pose"');
    expect(events.some((e) => e.type === 'token')).toBe(false);
  });
});

describe('a bad model file', () => {
  let dir: string;
  beforeAll(async () => {
    dir = await mkdtemp(join(tmpdir(), 'hal-gguf-'));
  });
  afterAll(async () => {
    await rm(dir, { recursive: true, force: true });
  });

  it(
    'a truncated GGUF is MODEL_INVALID, naming the file',
    async () => {
      const cut = join(dir, 'cut.gguf');
      const source = await open(defaultModelFile(), 'r');
      const head = Buffer.alloc(1 << 20);
      await source.read(head, 0, head.length, 0);
      await source.close();
      const target = await open(cut, 'w');
      await target.write(head);
      await target.close();
      await expect(
        createLocalChatProvider({ modelFile: cut, threads: 1, gpu: false }),
      ).rejects.toMatchObject({ code: 'MODEL_INVALID', message: expect.stringContaining(cut) });
    },
    MODEL_MS,
  );

  it('a missing file is MODEL_MISSING before llama.cpp is touched', async () => {
    await expect(
      createLocalChatProvider({ modelFile: join(dir, 'none.gguf') }),
    ).rejects.toMatchObject({ code: 'MODEL_MISSING' });
  });
});
