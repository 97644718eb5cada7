import { describe, expect, it } from 'vitest';
import { retryableStatus, retryAfterMs } from './retry.js';

describe('retryAfterMs', () => {
  it('reads retry-after-ms first, then Retry-After in seconds or as an HTTP date', () => {
    expect(retryAfterMs(new Headers({ 'retry-after-ms': '250', 'retry-after': '9' }))).toBe(250);
    expect(retryAfterMs(new Headers({ 'retry-after': '2' }))).toBe(2000);
    const now = Date.parse('2026-01-01T00:00:00Z');
    expect(retryAfterMs(new Headers({ 'retry-after': 'Thu, 01 Jan 2026 00:00:03 GMT' }), now)).toBe(
      3000,
    );
  });

  it('gives undefined for a missing, negative or unreadable header', () => {
    expect(retryAfterMs(new Headers())).toBeUndefined();
    expect(retryAfterMs(new Headers({ 'retry-after': '-1' }))).toBeUndefined();
    expect(retryAfterMs(new Headers({ 'retry-after': 'soon' }))).toBeUndefined();
  });
});

describe('retryableStatus', () => {
  it('retries 408, 429 and 5xx, not other client errors', () => {
    expect([408, 429, 500, 503].map(retryableStatus)).toEqual([true, true, true, true]);
    expect([400, 401, 403, 404, 422].map(retryableStatus)).toEqual([
      false,
      false,
      false,
      false,
      false,
    ]);
  });
});
