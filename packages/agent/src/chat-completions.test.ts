import { describe, expect, it } from 'vitest';
import { postChatCompletion } from './chat-completions.js';
import type { ChatEndpoint } from './chat-completions.js';
import { AgentError } from './errors.js';

/** A fetch that answers the scripted responses in turn and counts the requests. */
function scriptedFetch(responses: Array<() => Response>): { fetch: typeof fetch; calls: number } {
  const state = { calls: 0, fetch: undefined as unknown as typeof fetch };
  state.fetch = (() => {
    const next = responses[state.calls];
    state.calls += 1;
    if (next === undefined) throw new Error('no more scripted responses');
    return Promise.resolve(next());
  }) as typeof fetch;
  return state;
}

function endpoint(fetchImpl: typeof fetch, maxRetries: number): ChatEndpoint {
  return {
    url: 'http://127.0.0.1:1/v1/chat/completions',
    apiKey: undefined,
    requestTimeoutMs: 1000,
    retry: { maxRetries, baseDelayMs: 1, maxDelayMs: 5000 },
    fetch: fetchImpl,
  };
}

const ok = () => new Response(JSON.stringify({ answer: 42 }), { status: 200 });
const tooMany = (headers: Record<string, string>) => () =>
  new Response('{"error":"slow down"}', { status: 429, headers });

describe('postChatCompletion', () => {
  it('waits what a 429 asks for (retry-after-ms) before the next attempt', async () => {
    const script = scriptedFetch([tooMany({ 'retry-after-ms': '20' }), ok]);
    const delays: number[] = [];
    const value = await postChatCompletion(
      endpoint(script.fetch, 2),
      { model: 'm' },
      (reply) => (reply as { answer: number }).answer,
      new AbortController().signal,
      (info) => delays.push(info.delayMs),
    );
    expect(value).toBe(42);
    expect(script.calls).toBe(2);
    expect(delays).toEqual([20]);
  });

  it('rejects with the status and the asked wait when it may not retry', async () => {
    const script = scriptedFetch([tooMany({ 'retry-after': '3' })]);
    const error = await postChatCompletion(
      endpoint(script.fetch, 0),
      { model: 'm' },
      (reply) => reply,
      new AbortController().signal,
      () => undefined,
    ).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(AgentError);
    expect((error as AgentError).code).toBe('HTTP');
    expect((error as AgentError).details).toMatchObject({ status: 429, retryAfterMs: 3000 });
    expect(script.calls).toBe(1);
  });

  it('ends the request with its error when the server asks for more than maxDelayMs', async () => {
    const script = scriptedFetch([tooMany({ 'retry-after': '60' }), ok]);
    const error = await postChatCompletion(
      endpoint(script.fetch, 3),
      { model: 'm' },
      (reply) => reply,
      new AbortController().signal,
      () => undefined,
    ).catch((e: unknown) => e);
    expect((error as Error).message).toContain('asks to wait 60000 ms, more than maxDelayMs 5000');
    expect(script.calls).toBe(1);
  });
});
