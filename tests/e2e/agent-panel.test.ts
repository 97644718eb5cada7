// The browser demo's Agent panel in Chromium against the fake OpenAI-compatible endpoint (with
// CORS, on another origin): a run whose tool calls and results stream into the panel and move
// the simulated robot, and a run the Stop button ends with the robot standing still. Every
// request the page makes goes to its own origin or to the endpoint, and only the endpoint gets
// the key.
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import type { FakeOpenAIServer } from '../helpers/fake-openai-server.js';
import { openDemoInChromium } from './demo-browser.js';
import type { DemoBrowser } from './demo-browser.js';

interface AgentHooks {
  agentRunning(): boolean;
  pose(): { x: number; y: number; yaw: number };
}

const call = (name: string, args: Record<string, unknown> = {}) => ({
  name,
  arguments: JSON.stringify(args),
});

describe('the sim-demo Agent panel in Chromium', () => {
  let demo: DemoBrowser;
  let endpoint: FakeOpenAIServer;
  let page: Page;
  const requests: Array<{ url: string; authorization: string | undefined }> = [];

  beforeAll(async () => {
    endpoint = await startFakeOpenAIServer([{ content: 'unused' }]);
    demo = await openDemoInChromium('agent-panel', { width: 1400, height: 1000 });
    page = demo.page;
    page.on('request', (request) =>
      requests.push({ url: request.url(), authorization: request.headers()['authorization'] }),
    );
  }, 120_000);

  afterAll(async () => {
    await demo?.close();
    await endpoint?.close();
  }, 30_000);

  const hooks = () =>
    page.evaluate(() => (window as unknown as { simDemo: AgentHooks }).simDemo.pose());
  const running = () =>
    page.evaluate(() => (window as unknown as { simDemo: AgentHooks }).simDemo.agentRunning());

  async function runInstruction(goal: string): Promise<void> {
    await page.locator('#agent-goal').fill(goal);
    await page.locator('#agent-run').click();
    await page.waitForFunction(
      () => (window as unknown as { simDemo: AgentHooks }).simDemo.agentRunning(),
      undefined,
      { timeout: 5_000 },
    );
  }

  it('streams the tool calls and results of a run, and Stop ends a run with the robot still', async () => {
    const { url } = demo;
    const origin = new URL(url).origin;
    await page.goto(`${url}?map=obstacles&speed=20`, { waitUntil: 'load', timeout: 30_000 });
    await page.waitForFunction(() => 'simDemo' in window, undefined, { timeout: 20_000 });
    await expect(page.locator('#agent-panel').textContent()).resolves.toContain(
      'sent only to the endpoint',
    );

    // A run: the robot starts at (-1.8, 0) facing +x.
    endpoint.script = [
      { content: 'Let me look first.', toolCalls: [call('get_pose')] },
      {
        content: null,
        toolCalls: [call('move_forward', { distanceCm: 20 }), call('capture_frame')],
      },
      { content: 'I moved 20 cm forward.' },
    ];
    await page.locator('#agent-url').fill(endpoint.baseUrl);
    await page.locator('#agent-model').fill('fake-model');
    await page.locator('#agent-key').fill('sk-browser');
    await runInstruction('Drive 20 cm forward and look.');
    await page.waitForFunction(
      () => document.getElementById('agent-log')?.textContent?.includes('Done: completed') ?? false,
      undefined,
      { timeout: 60_000 },
    );
    const log = (await page.locator('#agent-log li').allTextContents()).join('\n');
    expect(log).toContain('Model: Let me look first.');
    expect(log).toContain('→ move_forward {"distanceCm":20}');
    expect(log).toMatch(/✓ move_forward: \{"success":true/);
    expect(log).toMatch(/✓ capture_frame: .*\[frame\]/);
    expect(log).toContain('Model: I moved 20 cm forward.');
    const after = await hooks();
    expect(after.x).toBeCloseTo(-1.6, 2);
    // The frame went to the model as an image.
    const third = endpoint.requests.at(-1)?.body.messages?.at(-1);
    expect(JSON.stringify(third)).toContain('data:image/jpeg;base64,');
    // The settings live in this tab's sessionStorage only.
    const stored = await page.evaluate(() => ({
      session: sessionStorage.getItem('hal-sim-demo:agent'),
      local: localStorage.length,
      cookie: document.cookie,
    }));
    expect(stored.session).toContain('sk-browser');
    expect(stored).toMatchObject({ local: 0, cookie: '' });

    // A run that drives on while the model thinks forever: Stop ends it and the robot halts.
    endpoint.script = [
      { content: null, toolCalls: [call('drive', { left: 200, right: 200 })] },
      { hang: true },
    ];
    const before = await hooks();
    await runInstruction('Drive until I say stop.');
    await page.waitForFunction(
      (x0) => (window as unknown as { simDemo: AgentHooks }).simDemo.pose().x > x0 + 0.02,
      before.x,
      { timeout: 30_000 },
    );
    await page.locator('#agent-stop').click();
    await page.waitForFunction(
      () => document.getElementById('agent-log')?.textContent?.includes('Done: aborted') ?? false,
      undefined,
      { timeout: 10_000 },
    );
    expect(await running()).toBe(false);
    const stopped = await hooks();
    await page.waitForTimeout(500);
    const later = await hooks();
    expect(later.x).toBeCloseTo(stopped.x, 3);
    expect((await page.locator('#agent-log li').allTextContents()).join('\n')).toContain('→ stop');

    // Requests went to the page's origin and the endpoint only; the key to the endpoint only.
    for (const request of requests) {
      const to = new URL(request.url);
      if (to.protocol === 'data:') continue;
      expect([origin, new URL(endpoint.baseUrl).origin]).toContain(to.origin);
      if (request.authorization !== undefined) expect(request.url).toContain(endpoint.baseUrl);
    }
    expect(requests.some((r) => r.authorization === 'Bearer sk-browser')).toBe(true);
    expect(demo.problems).toEqual([]);
  }, 180_000); // a build, a browser and two runs on a loaded machine
});
