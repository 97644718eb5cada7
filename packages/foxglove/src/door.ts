// Who may open the live view: the same rule as `hal serve`'s WebSocket door (a token, else
// loopback programs and trusted pages), plus the desktop viewers. Foxglove and Lichtblick on the
// desktop are Electron apps whose pages load from `file://`, and send that as their Origin; no web
// page can send it (a browser sends `null` for a file or sandboxed page, which stays refused).
import type { IncomingMessage } from 'node:http';
import { doorRefusal } from '@hal/remote/server';
import type { DoorRefusal, DoorWords } from '@hal/remote/server';

/** The Origin the desktop apps send. */
export const DESKTOP_ORIGIN = 'file://';

/** Why an upgrade is refused: its HTTP status and a sentence for the viewer. */
export type FoxgloveDoorRefusal = DoorRefusal;

/** The live view's door: the token in the URL, the option that trusts a page, the desktop apps. */
const FOXGLOVE_DOOR: DoorWords = {
  tokenRequired: 'a token is required: open ws://HOST:PORT/?token=TOKEN',
  trustOrigin: () => "trust it with --foxglove-allow-origin (serveFoxglove's allowedOrigins)",
  programOrigins: new Set([DESKTOP_ORIGIN]),
};

/** Undefined when `request` may connect, else why not. */
export function foxgloveDoorRefusal(
  request: IncomingMessage,
  token: string | undefined,
  allowedOrigins: ReadonlySet<string>,
): FoxgloveDoorRefusal | undefined {
  return doorRefusal(request, token, allowedOrigins, FOXGLOVE_DOOR);
}
