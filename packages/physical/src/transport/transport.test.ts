import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
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

describe('ReplyMatcher timing (fake clock)', () => {
  beforeEach(() => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'performance'] });
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it('arms one timer for all its requests, not one per request', async () => {
    const matcher = new ReplyMatcher();
    for (let seq = 1; seq <= 100; seq++) {
      const answered = matcher.request(seq, async () => {
        queueMicrotask(() => matcher.deliver(reply(seq)));
      });
      await answered;
    }
    expect(vi.getTimerCount()).toBeLessThanOrEqual(1);
    expect(matcher.stats()).toMatchObject({ sent: 100, received: 100, retries: 0, timeouts: 0 });
  });

  it('resends a short-timeout request on time while a long one waits', async () => {
    const matcher = new ReplyMatcher();
    const sends: number[] = [];
    const long = matcher
      .requestWith(
        1,
        (done) => {
          sends.push(1);
          done();
        },
        { timeoutMs: 2000, attempts: 1 },
      )
      .catch((error: unknown) => error);
    const short = matcher.requestWith(
      2,
      (done) => {
        sends.push(2);
        done();
      },
      { timeoutMs: 20, attempts: 3 },
    );
    await vi.advanceTimersByTimeAsync(45);
    expect(sends).toEqual([1, 2, 2, 2]);
    matcher.deliver(reply(2));
    await expect(short).resolves.toMatchObject({ seq: 2 });
    await vi.advanceTimersByTimeAsync(2000);
    expect(await long).toMatchObject({ code: 'TIMEOUT' });
    expect(matcher.stats()).toMatchObject({ sent: 4, retries: 2, timeouts: 1, received: 1 });
  });

  it('counts a failed send as a used attempt and sends again at once, keeping its error as the cause', async () => {
    const matcher = new ReplyMatcher();
    let sends = 0;
    const failing = matcher.requestWith(
      5,
      (done) => {
        sends += 1;
        done(new Error('EHOSTUNREACH'));
      },
      { timeoutMs: 1000, attempts: 3 },
    );
    await expect(failing).rejects.toMatchObject({
      code: 'TIMEOUT',
      cause: { message: 'EHOSTUNREACH' },
    });
    expect(sends).toBe(3);
    expect(vi.getTimerCount()).toBe(0);
  });
});

describe('ReplyMatcher with a caller that resends on its own (the hello)', () => {
  beforeEach(() => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'performance'] });
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  /** The caller's loop: one transport request per attempt, the same seq, until a reply. */
  async function resendUntilAnswered(
    matcher: ReplyMatcher,
    answerOnAttempt: number,
    of: number,
  ): Promise<unknown> {
    for (let attempt = 1; ; attempt++) {
      const sent = matcher.request(
        9,
        async () => {
          if (attempt === answerOnAttempt) queueMicrotask(() => matcher.deliver(reply(9)));
        },
        { timeoutMs: 20, attempts: 1, callerAttempt: { attempt, of } },
      );
      const outcome = sent.then(
        () => 'answered',
        (error: unknown) => error,
      );
      await vi.advanceTimersByTimeAsync(25);
      const settled = await outcome;
      if (settled === 'answered' || attempt >= of) return settled;
    }
  }

  it('counts its lost attempts as retries, not timeouts, when a later attempt is answered', async () => {
    const matcher = new ReplyMatcher();
    expect(await resendUntilAnswered(matcher, 3, 5)).toBe('answered');
    expect(matcher.stats()).toMatchObject({ sent: 3, retries: 2, timeouts: 0, received: 1 });
  });

  it('counts one timeout when its last attempt goes unanswered too', async () => {
    const matcher = new ReplyMatcher();
    expect(await resendUntilAnswered(matcher, 0, 3)).toMatchObject({ code: 'TIMEOUT' });
    expect(matcher.stats()).toMatchObject({ sent: 3, retries: 2, timeouts: 1, received: 0 });
  });
});
