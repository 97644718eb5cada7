// The agent loop's failures and caps against the fake endpoint over real HTTP: retries on 429 and
// 5xx (honouring Retry-After, bounded), a server that never answers, the step and time caps, and
// the caller's abort. A fake executor stands in for the robot where the robot does not matter.
import { AgentError, runAgent } from '@hal/agent';
import { describe, expect, it } from 'vitest';
import { call, endpoint, fakeExecutor, recorder, serve } from './fixtures.js';

const goal = 'Look around.';

describe('runAgent retries', () => {
  it('waits as a 429 asks (Retry-After) and goes on when the next attempt succeeds', async () => {
    const s = await serve([
      { status: 429, body: '{"error":{"message":"slow down"}}', headers: { 'retry-after': '1' } },
      { content: 'Done.' },
    ]);
    const { events, onEvent } = recorder();
    const outcome = await runAgent({
      goal,
      executor: fakeExecutor(),
      endpoint: endpoint(s),
      onEvent,
    });
    expect(outcome).toMatchObject({ reason: 'completed', steps: 1, text: 'Done.' });
    expect(s.requests).toHaveLength(2);
    expect(events.filter((e) => e.type === 'retry')).toEqual([
      expect.objectContaining({ step: 1, attempt: 1, delayMs: 1000, status: 429 }),
    ]);
    // It did wait the second the server asked for (less a little for clock granularity).
    expect(s.requests[1]!.at - s.requests[0]!.at).toBeGreaterThanOrEqual(950);
  });

  it('gives up with an HTTP error after the last retry of a server that keeps failing', async () => {
    const s = await serve([{ status: 500, body: 'upstream exploded' }]);
    const { events, onEvent } = recorder();
    const outcome = await runAgent({
      goal,
      executor: fakeExecutor(),
      endpoint: endpoint(s),
      retry: { maxRetries: 2, baseDelayMs: 20 },
      onEvent,
    });
    expect(outcome.reason).toBe('error');
    expect(outcome.error).toBeInstanceOf(AgentError);
    expect(outcome.error).toMatchObject({ code: 'HTTP', details: { status: 500 } });
    expect(outcome.error?.message).toContain('upstream exploded');
    expect(s.requests).toHaveLength(3);
    expect(events.filter((e) => e.type === 'retry').map((e) => e.attempt)).toEqual([1, 2]);
    // The error, then the stop the loop runs at every end but 'completed', then done.
    expect(events.map((e) => e.type).slice(-4)).toEqual([
      'error',
      'tool_call',
      'tool_result',
      'done',
    ]);
  });

  it('does not retry a request the server rejects (HTTP 401)', async () => {
    const s = await serve([{ status: 401, body: '{"error":{"message":"bad key"}}' }]);
    const outcome = await runAgent({ goal, executor: fakeExecutor(), endpoint: endpoint(s) });
    expect(outcome).toMatchObject({
      reason: 'error',
      error: { code: 'HTTP', details: { status: 401 } },
    });
    expect(s.requests).toHaveLength(1);
    // the message names the URL, what the server said, and whether a key was sent
    const { error } = outcome as { error: AgentError };
    const url = `${endpoint(s).baseUrl}/chat/completions`;
    expect(error.message).toBe(
      `HTTP 401 from ${url}: {"error":{"message":"bad key"}} (the API key was refused)`,
    );
  });

  it('ends at once when the server asks for a longer wait than maxDelayMs', async () => {
    const s = await serve([{ status: 429, body: 'quota', headers: { 'retry-after': '3600' } }]);
    const outcome = await runAgent({
      goal,
      executor: fakeExecutor(),
      endpoint: endpoint(s),
      retry: { maxDelayMs: 5_000 },
    });
    expect(outcome.reason).toBe('error');
    expect(outcome.error?.message).toContain('3600000 ms');
    expect(s.requests).toHaveLength(1);
    expect(outcome.elapsedMs).toBeLessThan(3_000);
  });

  it('times out a server that never answers, retries, then ends with TIMEOUT', async () => {
    const s = await serve([{ hang: true }]);
    const outcome = await runAgent({
      goal,
      executor: fakeExecutor(),
      endpoint: endpoint(s),
      requestTimeoutMs: 300,
      retry: { maxRetries: 1, baseDelayMs: 10 },
    });
    expect(outcome).toMatchObject({ reason: 'error', error: { code: 'TIMEOUT' } });
    expect(s.requests).toHaveLength(2);
    expect(outcome.elapsedMs).toBeLessThan(10_000);
  });

  it('rejects bad options with a CONFIG error that names them', async () => {
    const executor = fakeExecutor();
    const base = { goal, executor, endpoint: { baseUrl: 'http://127.0.0.1:1/v1', model: 'm' } };
    await expect(runAgent({ ...base, caps: { maxSteps: 0 } })).rejects.toMatchObject({
      code: 'CONFIG',
      message: expect.stringContaining('caps.maxSteps'),
    });
    await expect(
      runAgent({ ...base, endpoint: { baseUrl: 'not a url', model: 'm' } }),
    ).rejects.toMatchObject({ code: 'CONFIG', message: expect.stringContaining('baseUrl') });
    await expect(runAgent({ ...base, goal: ' ' })).rejects.toMatchObject({ code: 'CONFIG' });
    expect(executor.calls).toEqual([]);
  });
});

describe('runAgent caps and abort', () => {
  it('stops after maxSteps requests when the model keeps calling tools, and stops the robot', async () => {
    const s = await serve([{ content: null, toolCalls: [call('get_pose')] }]);
    const executor = fakeExecutor();
    const outcome = await runAgent({
      goal,
      executor,
      endpoint: endpoint(s),
      caps: { maxSteps: 3 },
    });
    expect(outcome).toMatchObject({ reason: 'max_steps', steps: 3 });
    expect(s.requests).toHaveLength(3);
    expect(executor.calls.map((c) => c.name)).toEqual(['get_pose', 'get_pose', 'get_pose', 'stop']);
  });

  it('stops when maxMs has passed, in the middle of a tool call', async () => {
    const s = await serve([{ content: null, toolCalls: [call('wait')] }]);
    const executor = fakeExecutor(400);
    const outcome = await runAgent({
      goal,
      executor,
      endpoint: endpoint(s),
      caps: { maxSteps: 100, maxMs: 1_000 },
    });
    expect(outcome.reason).toBe('max_ms');
    expect(outcome.steps).toBeGreaterThanOrEqual(1);
    expect(outcome.steps).toBeLessThan(100);
    expect(executor.calls.at(-1)?.name).toBe('stop');
    expect(outcome.elapsedMs).toBeLessThan(5_000);
  });

  it('stops at once when the signal aborts during a tool call, and runs the stop tool', async () => {
    const s = await serve([{ content: null, toolCalls: [call('wait')] }]);
    const executor = fakeExecutor(30_000);
    const controller = new AbortController();
    const { events, onEvent } = recorder();
    const outcome = await runAgent({
      goal,
      executor,
      endpoint: endpoint(s),
      signal: controller.signal,
      onEvent: (e) => {
        onEvent(e);
        if (e.type === 'tool_call' && e.name === 'wait') setTimeout(() => controller.abort(), 50);
      },
    });
    expect(outcome).toMatchObject({ reason: 'aborted', steps: 1 });
    expect(executor.calls.map((c) => c.name)).toEqual(['wait', 'stop']);
    expect(events.at(-1)).toMatchObject({ type: 'done', reason: 'aborted' });
    // It did not wait for the 30 s tool call.
    expect(outcome.elapsedMs).toBeLessThan(10_000);
  });

  it('stops at once when the signal aborts while the model is thinking', async () => {
    const s = await serve([{ hang: true }]);
    const controller = new AbortController();
    setTimeout(() => controller.abort(), 200);
    const outcome = await runAgent({
      goal,
      executor: fakeExecutor(),
      endpoint: endpoint(s),
      signal: controller.signal,
    });
    expect(outcome.reason).toBe('aborted');
    expect(outcome.elapsedMs).toBeLessThan(10_000);
  });
});
