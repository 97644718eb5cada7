// Who may open the live view: the same rule as `hal serve`'s WebSocket door (a token, else
// loopback programs and trusted pages), plus the desktop viewers. Foxglove and Lichtblick on the
// desktop are Electron apps whose pages load from `file://`, and send that as their Origin; no web
// page can send it (a browser sends `null` for a file or sandboxed page, which stays refused).
import type { IncomingMessage } from 'node:http';
import { presentedToken, tokenMatches } from '@hal/remote/server';
import type { DoorRefusal } from '@hal/remote/server';
import { browserRefusal } from '@hal/types';

/** The Origin the desktop apps send. */
export const DESKTOP_ORIGIN = 'file://';

/** Why an upgrade is refused: its HTTP status and a sentence for the viewer. */
export type FoxgloveDoorRefusal = DoorRefusal;

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
