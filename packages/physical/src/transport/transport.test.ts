import { describe, expect, it } from 'vitest';
import { ReplyMatcher } from './transport.js';

const reply = (seq: number) => ({ ok: true as const, reply: { seq, ok: true } });

describe('ReplyMatcher', () => {
  it('resolves a request with the reply that echoes its seq', async () => {
    const matcher = new ReplyMatcher();
    const pending = matcher.request(7, async () => {
      queueMicrotask(() => matcher.deliver(reply(7)));
    });
    await expect(pending).resolves.toMatchObject({ seq: 7, ok: true });
    expect(matcher.stats()).toMatchObject({ sent: 1, received: 1, timeouts: 0 });
  });

  it('wakes a request waiting for its reply when closed, after many requests have come and gone', async () => {
    const matcher = new ReplyMatcher();
    for (let seq = 1; seq <= 100; seq++) {
      const answered = matcher.request(seq, async () => {
        queueMicrotask(() => matcher.deliver(reply(seq)));
      });
      await answered;
    }
    const waiting = matcher.request(101, async () => undefined, { timeoutMs: 60_000 });
    const stuckInSend = matcher.request(102, () => new Promise<void>(() => undefined));
    matcher.close();
    await expect(waiting).rejects.toMatchObject({ code: 'NOT_CONNECTED' });
    await expect(stuckInSend).rejects.toMatchObject({ code: 'NOT_CONNECTED' });
    await expect(matcher.request(103, async () => undefined)).rejects.toMatchObject({
      code: 'NOT_CONNECTED',
    });
  });
});
