import { createHash, timingSafeEqual } from 'node:crypto';
import type { IncomingMessage } from 'node:http';
import { HalError } from '@hal/types';

/** True for an address only this machine can reach. */
export function isLoopback(host: string): boolean {
  return host === 'localhost' || host === '::1' || /^127\.\d+\.\d+\.\d+$/.test(host);
}

/** Refuses to serve beyond this machine without a token. */
export function checkBinding(host: string, token: string | undefined): void {
  if (!isLoopback(host) && (token === undefined || token.length === 0)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `serving on "${host}" (not loopback) needs a token: pass "token" (hal serve --token), or bind to 127.0.0.1`,
      { details: { parameter: 'token', host } },
    );
  }
  if (token !== undefined && token.length > 0 && token.length < 16) {
    throw new HalError('INVALID_PARAMETER', '"token" must be at least 16 characters', {
      details: { parameter: 'token' },
    });
  }
}

/** The token a client presented: `Authorization: Bearer ...`, else the `token` query parameter. */
export function presentedToken(request: IncomingMessage): string | undefined {
  const header = request.headers.authorization;
  if (header !== undefined) {
    const match = /^Bearer\s+(\S+)$/i.exec(header);
    if (match !== null) return match[1];
  }
  const url = new URL(request.url ?? '/', 'http://localhost');
  return url.searchParams.get('token') ?? undefined;
}

/** Compares tokens in constant time (digests of equal length, whatever the inputs' lengths). */
export function tokenMatches(expected: string, presented: string | undefined): boolean {
  if (presented === undefined) return false;
  const a = createHash('sha256').update(expected).digest();
  const b = createHash('sha256').update(presented).digest();
  return timingSafeEqual(a, b);
}
