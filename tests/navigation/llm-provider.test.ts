import {
  GoalSeekingProvider,
  NavigationBridge,
  NavigationError,
  OccupancyGrid,
  OpenAICompatibleProvider,
  decisionJsonSchema,
} from '@hal/navigation';
import type { DecisionContext, NavigationDecision } from '@hal/navigation';
import { SimulationHAL, World } from '@hal/simulation';
import { afterEach, describe, expect, it } from 'vitest';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import type { FakeOpenAIServer, ScriptedReply } from '../helpers/fake-openai-server.js';

const FRAME = 'data:image/jpeg;base64,/9j/AAAA';
const valid: NavigationDecision = {
  reasoning: 'The goal is ahead and the way is clear.',
  action: { type: 'MOVE_TO', x: 1.2, y: 0.5 },
  goal_reached: false,
};

let server: FakeOpenAIServer | undefined;
afterEach(async () => {
  await server?.close();
  server = undefined;
});

async function serve(script: ScriptedReply[]): Promise<FakeOpenAIServer> {
  server = await startFakeOpenAIServer(script);
  return server;
}

function context(overrides: Partial<DecisionContext> = {}): DecisionContext {
  const grid = new OccupancyGrid();
  grid.seedFromMap({ arena: { width: 5, height: 5 } });
  return {
    cycle: 3,
    goal: { x: 1.2, y: 0.5 },
    goalToleranceM: 0.1,
    pose: { x: 0, y: 0, yaw: 0 },
    grid,
    frame: FRAME,
    ...overrides,
  };
}

function provider(
  baseUrl: string,
  extra: Partial<ConstructorParameters<typeof OpenAICompatibleProvider>[0]> = {},
) {
  return new OpenAICompatibleProvider({
    baseUrl,
    apiKey: 'sk-test',
    model: 'test-vision-model',
    timeoutMs: 5_000,
    env: {},
    ...extra,
  });
}

const signal = () => new AbortController().signal;

describe('OpenAICompatibleProvider', () => {
  it('sends the frame as an image, the world summary and the goal, and returns the valid decision', async () => {
    const s = await serve([{ content: JSON.stringify(valid) }]);
    const decision = await provider(s.baseUrl).decide(context(), signal());
    expect(decision).toEqual(valid);
    expect(s.requests).toHaveLength(1);
    const request = s.requests[0];
    expect(request?.path).toBe('/v1/chat/completions');
    expect(request?.headers['authorization']).toBe('Bearer sk-test');
    expect(request?.body.model).toBe('test-vision-model');
    expect(request?.body.response_format?.type).toBe('json_schema');
    expect(request?.body.response_format?.json_schema?.name).toBe('navigation_decision');
    // The schema sent is the one generated from the zod schema, bounded to the world model.
    expect(request?.body.response_format?.json_schema?.schema).toEqual(
      decisionJsonSchema({ minX: -2.5, maxX: 2.5, minY: -2.5, maxY: 2.5 }),
    );
    const user = request?.body.messages?.find((m) => m.role === 'user');
    const parts = user?.content as { type: string; text?: string; image_url?: { url: string } }[];
    expect(parts.find((p) => p.type === 'image_url')?.image_url?.url).toBe(FRAME);
    const text = parts.find((p) => p.type === 'text')?.text ?? '';
    expect(text).toContain('reach the goal (1.20, 0.50) m');
    expect(text).toContain('Robot: at (0.00, 0.00) m');
    expect(text).toContain('Map (');
  });

  it('accepts a reply wrapped in a markdown code fence', async () => {
    const s = await serve([{ content: `\`\`\`json\n${JSON.stringify(valid)}\n\`\`\`` }]);
    expect(await provider(s.baseUrl).decide(context(), signal())).toEqual(valid);
  });

  it('accepts content given as a list of text parts', async () => {
    const text = JSON.stringify(valid);
    const s = await serve([
      {
        content: [
          { type: 'text', text: text.slice(0, 20) },
          { type: 'text', text: text.slice(20) },
        ],
      },
    ]);
    expect(await provider(s.baseUrl).decide(context(), signal())).toEqual(valid);
  });

  it('asks again, saying why, after a reply that is not JSON', async () => {
    const s = await serve([
      { content: 'I think we should go left {' },
      { content: JSON.stringify(valid) },
    ]);
    expect(await provider(s.baseUrl).decide(context(), signal())).toEqual(valid);
    expect(s.requests).toHaveLength(2);
    const messages = s.requests[1]?.body.messages ?? [];
    expect(messages.at(-2)).toEqual({ role: 'assistant', content: 'I think we should go left {' });
    expect(String(messages.at(-1)?.content)).toContain('not valid JSON');
  });

  it('asks again after a reply that breaks the schema, naming the problem', async () => {
    const outside = { ...valid, action: { type: 'MOVE_TO', x: 7, y: 0 } };
    const s = await serve([
      { content: JSON.stringify(outside) },
      { content: JSON.stringify(valid) },
    ]);
    expect(await provider(s.baseUrl).decide(context(), signal())).toEqual(valid);
    const feedback = String(s.requests[1]?.body.messages?.at(-1)?.content);
    expect(feedback).toContain('does not match the schema');
  });

  it('falls back to the fallback provider when every reply is invalid, and says so', async () => {
    const s = await serve([{ content: JSON.stringify({ action: 'FLY', reasoning: 1 }) }]);
    const llm = provider(s.baseUrl, { maxAttempts: 3, fallback: new GoalSeekingProvider() });
    const decision = await llm.decide(context(), signal());
    expect(s.requests).toHaveLength(3);
    expect(decision.action).toEqual({ type: 'MOVE_TO', x: 1.2, y: 0.5 });
    expect(decision.reasoning).toMatch(
      /^\[fallback goal-seeking: attempt 1: the reply broke the decision schema/,
    );
  });

  it('rejects with PROVIDER_ERROR when every reply is invalid and there is no fallback', async () => {
    const s = await serve([{ content: '{"reasoning": "no action"}' }]);
    const error = await provider(s.baseUrl, { maxAttempts: 2 })
      .decide(context(), signal())
      .catch((e: unknown) => e);
    expect(error).toBeInstanceOf(NavigationError);
    expect((error as NavigationError).code).toBe('PROVIDER_ERROR');
    expect(s.requests).toHaveLength(2);
  });

  it('gives up on a request that takes longer than timeoutMs, then retries', async () => {
    const s = await serve([{ hang: true }, { content: JSON.stringify(valid) }]);
    const decision = await provider(s.baseUrl, { timeoutMs: 300 }).decide(context(), signal());
    expect(decision).toEqual(valid);
    expect(s.requests).toHaveLength(2);
  });

  it('rejects naming the timeout when the server never answers', async () => {
    const s = await serve([{ hang: true }]);
    const error = await provider(s.baseUrl, { timeoutMs: 200, maxAttempts: 2 })
      .decide(context(), signal())
      .catch((e: unknown) => e);
    expect((error as NavigationError).code).toBe('PROVIDER_ERROR');
    expect((error as Error).message).toContain('no reply within 200 ms');
  });

  it('retries after HTTP 500 and 429', async () => {
    const s = await serve([
      { status: 500, body: '{"error":{"message":"overloaded"}}' },
      { status: 429, body: '{"error":{"message":"slow down"}}' },
      { content: JSON.stringify(valid) },
    ]);
    expect(await provider(s.baseUrl).decide(context(), signal())).toEqual(valid);
    expect(s.requests).toHaveLength(3);
  });

  it('waits as long as a 429 asks (retry-after-ms) before asking again', async () => {
    const s = await serve([
      {
        status: 429,
        body: '{"error":{"message":"slow down"}}',
        headers: { 'retry-after-ms': '700' },
      },
      { content: JSON.stringify(valid) },
    ]);
    expect(await provider(s.baseUrl).decide(context(), signal())).toEqual(valid);
    expect(s.requests).toHaveLength(2);
    const [first, second] = s.requests;
    // the provider's own pause after a first failure is at most 250 ms: 700 comes from the header
    expect((second?.at ?? 0) - (first?.at ?? 0)).toBeGreaterThanOrEqual(650);
  });

  it('gives up at once on a 429 that asks for a wait longer than 30 s', async () => {
    const s = await serve([
      { status: 429, body: '{"error":{"message":"slow down"}}', headers: { 'retry-after': '120' } },
      { content: JSON.stringify(valid) },
    ]);
    const error = await provider(s.baseUrl)
      .decide(context(), signal())
      .catch((e: unknown) => e);
    expect((error as NavigationError).code).toBe('PROVIDER_ERROR');
    expect((error as Error).message).toContain('asks to wait 120000 ms');
    expect(s.requests).toHaveLength(1);
  });

  it('does not retry after HTTP 401, and reports the status', async () => {
    const s = await serve([{ status: 401, body: '{"error":{"message":"bad key"}}' }]);
    const error = await provider(s.baseUrl)
      .decide(context(), signal())
      .catch((e: unknown) => e);
    expect((error as Error).message).toContain('HTTP 401');
    expect(s.requests).toHaveLength(1);
  });

  it('switches to json_object, with the schema in the prompt, when json_schema is refused', async () => {
    const s = await serve([
      { status: 400, body: '{"error":{"message":"response_format json_schema not supported"}}' },
      { content: JSON.stringify(valid) },
    ]);
    const llm = provider(s.baseUrl);
    expect(await llm.decide(context(), signal())).toEqual(valid);
    expect(s.requests[1]?.body.response_format).toEqual({ type: 'json_object' });
    const parts = s.requests[1]?.body.messages?.[1]?.content as { type: string; text?: string }[];
    expect(parts[0]?.text).toContain('matching this JSON Schema');
  });

  it('stops at once when its signal is aborted', async () => {
    const s = await serve([{ hang: true }]);
    const controller = new AbortController();
    const pending = provider(s.baseUrl, { timeoutMs: 30_000 }).decide(context(), controller.signal);
    setTimeout(() => controller.abort(), 50);
    const error = await pending.catch((e: unknown) => e);
    expect((error as NavigationError).code).toBe('ABORTED');
  });

  it('reads the URL, the key and the model from OPENAI_BASE_URL, OPENAI_API_KEY and NAV_MODEL', async () => {
    const s = await serve([{ content: JSON.stringify(valid) }]);
    const llm = new OpenAICompatibleProvider({
      env: { OPENAI_BASE_URL: s.baseUrl, OPENAI_API_KEY: 'from-env', NAV_MODEL: 'env-model' },
    });
    expect(llm.name).toBe('llm:env-model');
    await llm.decide(context(), signal());
    expect(s.requests[0]?.headers['authorization']).toBe('Bearer from-env');
    expect(s.requests[0]?.body.model).toBe('env-model');
  });

  it('refuses to start without a model or with a bad URL, naming the setting', () => {
    expect(() => new OpenAICompatibleProvider({ env: {} })).toThrow('NAV_MODEL');
    expect(
      () => new OpenAICompatibleProvider({ env: {}, model: 'm', baseUrl: 'not a url' }),
    ).toThrow('"baseUrl"');
  });

  it('adds a picture of the occupancy grid when asked to', async () => {
    const s = await serve([{ content: JSON.stringify(valid) }]);
    await provider(s.baseUrl, { sendMapImage: true }).decide(context(), signal());
    const parts = s.requests[0]?.body.messages?.[1]?.content as {
      type: string;
      image_url?: { url: string };
    }[];
    const images = parts.filter((p) => p.type === 'image_url').map((p) => p.image_url?.url ?? '');
    expect(images).toHaveLength(2);
    expect(images[0]).toBe(FRAME);
    expect(images[1]).toMatch(/^data:image\/jpeg;base64,\/9j\//);
  });

  it('leaves the image out when told not to send frames', async () => {
    const s = await serve([{ content: JSON.stringify(valid) }]);
    const llm = provider(s.baseUrl, { sendFrame: false });
    expect(llm.wantsFrame).toBe(false);
    await llm.decide(context(), signal());
    const parts = s.requests[0]?.body.messages?.[1]?.content as { type: string }[];
    expect(parts.map((p) => p.type)).toEqual(['text']);
  });
});

describe('OpenAICompatibleProvider driving the navigation bridge on SimulationHAL', () => {
  it('reaches the goal on decisions from the server, sending a camera frame each cycle', async () => {
    const goal = { x: 1.5, y: 0.5 };
    const s = await serve([
      {
        content: JSON.stringify({
          reasoning: 'Heading for the goal.',
          action: { type: 'MOVE_TO', ...goal },
          goal_reached: false,
        }),
      },
    ]);
    const world = new World({ map: 'obstacles', seed: 3 });
    const hal = new SimulationHAL({ world, start: { x: -1.8, y: 0, yaw: 0 } });
    await hal.initialize();
    try {
      const bridge = new NavigationBridge({
        hal,
        provider: provider(s.baseUrl),
        grid: OccupancyGrid.fromMap(world.map),
      });
      const outcome = await bridge.run(goal);
      expect(outcome.status).toBe('reached');
      expect(s.requests.length).toBe(outcome.cycles);
      for (const request of s.requests) {
        const parts = request.body.messages?.[1]?.content as {
          type: string;
          image_url?: { url: string };
        }[];
        expect(parts.find((p) => p.type === 'image_url')?.image_url?.url).toMatch(
          /^data:image\/jpeg;base64,\/9j\//,
        );
      }
    } finally {
      await hal.cleanup();
    }
  });

  it('still reaches the goal through the fallback when the server only talks nonsense', async () => {
    const s = await serve([{ content: 'Sure! Moving now.' }]);
    const world = new World({ map: 'empty', seed: 1 });
    const hal = new SimulationHAL({ world });
    await hal.initialize();
    try {
      const llm = provider(s.baseUrl, { maxAttempts: 2, fallback: new GoalSeekingProvider() });
      const decisions: string[] = [];
      const bridge = new NavigationBridge({
        hal,
        provider: llm,
        grid: OccupancyGrid.fromMap(world.map),
      });
      bridge.on('decision', ({ decision }) => decisions.push(decision.reasoning));
      const outcome = await bridge.run({ x: 1, y: -1 });
      expect(outcome.status).toBe('reached');
      expect(decisions.every((r) => r.startsWith('[fallback goal-seeking'))).toBe(true);
    } finally {
      await hal.cleanup();
    }
  });
});
