// Who may open the live view: the same rule as `hal serve`'s WebSocket door (a token, else
// loopback programs and trusted pages), plus the desktop viewers. Foxglove and Lichtblick on the
// desktop are Electron apps whose pages load from `file://`, and send that as their Origin; no web
// page can send it (a browser sends `null` for a file or sandboxed page, which stays refused).
import { createHash, timingSafeEqual } from 'node:crypto';
import type { IncomingMessage } from 'node:http';
import { browserRefusal } from '@hal/types';

/** The Origin the desktop apps send. */
export const DESKTOP_ORIGIN = 'file://';

/** Why an upgrade is refused: its HTTP status and a sentence for the viewer. */
export interface FoxgloveDoorRefusal {
  status: 401 | 403;
  reason: string;
}

/** The token a viewer presented: `?token=` in its URL, else `Authorization: Bearer ...`. */
function presentedToken(request: IncomingMessage): string | undefined {
  const url = new URL(request.url ?? '/', 'http://localhost');
  const query = url.searchParams.get('token');
  if (query !== null) return query;
  const match = /^Bearer\s+(\S+)$/i.exec(request.headers.authorization ?? '');
  return match?.[1];
}

/** Constant-time comparison (digests of equal length, whatever the inputs' lengths). */
function tokenMatches(expected: string, presented: string | undefined): boolean {
  if (presented === undefined) return false;
  const a = createHash('sha256').update(expected).digest();
  const b = createHash('sha256').update(presented).digest();
  return timingSafeEqual(a, b);
}

/** Undefined when `request` may connect, else why not. */
export function foxgloveDoorRefusal(
  request: IncomingMessage,
  token: string | undefined,
  allowedOrigins: ReadonlySet<string>,
): FoxgloveDoorRefusal | undefined {
  if (token !== undefined) {
    const presented = presentedToken(request);
    if (tokenMatches(token, presented)) return undefined;
    return {
      status: 401,
      reason:
        presented === undefined
          ? 'a token is required: open ws://HOST:PORT/?token=TOKEN'
          : 'the token is wrong',
    };
  }
  const { host, origin } = request.headers;
  const refused = browserRefusal(
    { host, origin: origin === DESKTOP_ORIGIN ? undefined : origin },
    allowedOrigins,
  );
  if (refused === undefined) return undefined;
  const remedy =
    refused.header === 'origin'
      ? `trust it with --foxglove-allow-origin (serveFoxglove's allowedOrigins), or serve with a token`
      : 'connect to 127.0.0.1 or localhost, or serve with a token';
  return { status: 403, reason: `${refused.reason}: ${remedy}` };
}
