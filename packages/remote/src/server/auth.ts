import { createHash, timingSafeEqual } from 'node:crypto';
import type { IncomingMessage } from 'node:http';
import type { Duplex } from 'node:stream';
import { browserRefusal, isLoopback, trustedOrigin } from '@hal/runtime';
import { HalError } from '@hal/types';

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

/** Why an upgrade is refused before the hello: its HTTP status and a sentence for the client. */
export interface DoorRefusal {
  status: 401 | 403;
  reason: string;
}

/** Answers a refused WebSocket upgrade with its HTTP status and reason, and closes the socket. */
export function refuseUpgrade(socket: Duplex, refused: DoorRefusal): void {
  const body = `${refused.reason}\n`;
  socket.end(
    `HTTP/1.1 ${refused.status} ${refused.status === 401 ? 'Unauthorized' : 'Forbidden'}\r\n` +
      'Content-Type: text/plain; charset=utf-8\r\n' +
      `Content-Length: ${Buffer.byteLength(body)}\r\n` +
      `Connection: close\r\n\r\n${body}`,
  );
}

/** What a door says in its refusals, and which origins it takes for programs. */
export interface DoorWords {
  /** The 401 to a client that presented no token: how to present one. */
  tokenRequired: string;
  /** The remedy for a page of a refused origin (as browsers write it). */
  trustOrigin: (origin: string) => string;
  /** Origins no web page can send, that programs do (a desktop app's): let in as no page. */
  programOrigins?: ReadonlySet<string>;
}

/** `hal serve`'s WebSocket door. */
const SERVE_DOOR: DoorWords = {
  tokenRequired: 'a token is required (Authorization: Bearer TOKEN, or ?token=TOKEN)',
  trustOrigin: (origin) =>
    `trust it with hal serve --allow-origin ${origin} (serveHal's allowedOrigins)`,
};

/**
 * Who may open the door. With a token, whoever presents it (401 otherwise), from any page or
 * program. Without one (so on loopback), programs, and web pages served from this machine or
 * from `allowedOrigins`; a page from anywhere else, or a request naming a Host that is not
 * loopback (DNS rebinding), is refused 403.
 */
export function doorRefusal(
  request: IncomingMessage,
  token: string | undefined,
  allowedOrigins: ReadonlySet<string>,
  words: DoorWords = SERVE_DOOR,
): DoorRefusal | undefined {
  if (token !== undefined) {
    const presented = presentedToken(request);
    if (tokenMatches(token, presented)) return undefined;
    return {
      status: 401,
      reason: presented === undefined ? words.tokenRequired : 'the token is wrong',
    };
  }
  const { host, origin } = request.headers;
  const fromProgram = origin !== undefined && words.programOrigins?.has(origin) === true;
  const refused = browserRefusal(
    { host, origin: fromProgram ? undefined : origin },
    allowedOrigins,
  );
  if (refused === undefined) return undefined;
  const remedy =
    refused.header === 'origin'
      ? `${words.trustOrigin(originOf(refused.value))}, or serve with a token`
      : 'connect to 127.0.0.1 or localhost, or serve with a token';
  return { status: 403, reason: `${refused.reason}: ${remedy}` };
}

/** The origin to name in a remedy: the sent one as browsers write it, else a placeholder. */
function originOf(value: string): string {
  try {
    return trustedOrigin(value);
  } catch {
    return 'ORIGIN';
  }
}
