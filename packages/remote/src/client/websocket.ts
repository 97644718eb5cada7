// The little of the WebSocket API the client uses: the browser's global WebSocket and the `ws`
// package both provide it.

/** A WebSocket as the client uses it. */
export interface WebSocketLike {
  readonly readyState: number;
  onopen: ((event: unknown) => void) | null;
  onmessage: ((event: { data: unknown }) => void) | null;
  onclose: ((event: { code: number; reason: string }) => void) | null;
  onerror: ((event: unknown) => void) | null;
  send(data: string): void;
  close(code?: number, reason?: string): void;
}

/** A WebSocket constructor: `globalThis.WebSocket`, or `ws`'s (which also takes options). */
export type WebSocketConstructor = new (
  url: string,
  protocols?: string | string[],
  options?: { headers?: Record<string, string> },
) => WebSocketLike;

/** The open state of a WebSocket. */
export const OPEN = 1;

/**
 * The constructor to use: the one given; in Node `ws` (it sends the token as a header and reports
 * the HTTP status of a refused upgrade, which Node's global WebSocket hides); else the global
 * WebSocket (browsers). `ws` is loaded only in Node, so a browser bundle never pulls it in.
 */
export async function resolveWebSocket(
  given: WebSocketConstructor | undefined,
): Promise<{ ctor: WebSocketConstructor; headers: boolean }> {
  if (given !== undefined) return { ctor: given, headers: false };
  const global = (globalThis as { WebSocket?: unknown }).WebSocket;
  const inNode =
    typeof (globalThis as { process?: { versions?: { node?: string } } }).process?.versions
      ?.node === 'string';
  if (!inNode && typeof global === 'function') {
    return { ctor: global as WebSocketConstructor, headers: false };
  }
  const module = 'ws';
  try {
    const ws = (await import(/* @vite-ignore */ module)) as { WebSocket: unknown };
    return { ctor: ws.WebSocket as WebSocketConstructor, headers: true };
  } catch (error) {
    if (typeof global === 'function') {
      return { ctor: global as WebSocketConstructor, headers: false };
    }
    throw error;
  }
}
