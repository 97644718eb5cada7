// The door a server on loopback keeps against web pages. A browser applies no same-origin rule to
// a WebSocket (nor to a simple POST), so any page the user opens could reach a server on
// 127.0.0.1, directly or through a DNS-rebound name; what gives such a page away is its request's
// `Origin`, and a rebound name its `Host`. Programs (the CLI, Node clients) send no `Origin`.
import { HalError } from '@hal/types';

/** True for an address or name only this machine can reach: `localhost`, 127.0.0.0/8, `::1`. */
export function isLoopback(host: string): boolean {
  const name = host.toLowerCase().replace(/^\[|\]$/g, '');
  return name === 'localhost' || name === '::1' || /^127\.\d+\.\d+\.\d+$/.test(name);
}

/** The host name of a `Host` header (`127.0.0.1:8765`, `[::1]:80`), or undefined if unreadable. */
export function hostOfHeader(header: string | undefined): string | undefined {
  if (header === undefined || header === '') return undefined;
  try {
    const url = new URL(`http://${header}`);
    // a Host header is host[:port] and nothing else
    if (url.username !== '' || url.pathname !== '/' || url.search !== '' || url.hash !== '') {
      return undefined;
    }
    return url.hostname.replace(/^\[|\]$/g, '');
  } catch {
    return undefined;
  }
}

/**
 * An origin given to trust, as browsers send it: `scheme://host[:port]` (`https://robot.example`,
 * `http://192.168.1.20:5173`), normalised (lower case, no default port). Anything else (a path, a
 * bare host, `null`, `*`) is refused with `INVALID_PARAMETER`, so a mistyped origin never
 * silently trusts nothing or everything.
 */
export function trustedOrigin(value: string): string {
  let origin: string | undefined;
  try {
    const url = new URL(value);
    const bare =
      (url.protocol === 'http:' || url.protocol === 'https:') &&
      url.username === '' &&
      url.password === '' &&
      url.pathname === '/' &&
      !value.includes('?') &&
      !value.includes('#');
    if (bare) origin = url.origin;
  } catch {
    origin = undefined;
  }
  if (origin === undefined || origin === 'null') {
    throw new HalError(
      'INVALID_PARAMETER',
      `an origin to trust is "http(s)://host[:port]" as a browser sends it, got "${value}"`,
      { details: { parameter: 'allowedOrigins', received: value } },
    );
  }
  return origin;
}

/** The request headers the gate reads (Node's `IncomingMessage.headers` fits). */
export interface GateHeaders {
  host?: string | undefined;
  origin?: string | undefined;
}

/** Why a request was refused: the header at fault, its value, and a sentence saying why. */
export interface BrowserRefusal {
  header: 'host' | 'origin';
  value: string;
  reason: string;
}

/**
 * Why a request that presents no token is refused, or undefined when it may pass. Its `Host`
 * must name loopback (a DNS-rebound name does not), and its `Origin`, when it sends one (browsers
 * always do), must be loopback (a page served from this machine) or one of `allowed` (each from
 * {@link trustedOrigin}). A request without `Origin` comes from a program, not a web page.
 */
export function browserRefusal(
  headers: GateHeaders,
  allowed: ReadonlySet<string> = new Set(),
): BrowserRefusal | undefined {
  const host = hostOfHeader(headers.host);
  if (host === undefined || !isLoopback(host)) {
    return {
      header: 'host',
      value: headers.host ?? '',
      reason:
        headers.host === undefined
          ? 'the request names no Host'
          : `Host "${headers.host}" is not a loopback name (a name that resolves to this machine, as a DNS-rebound one does, is not trusted)`,
    };
  }
  const origin = headers.origin;
  if (origin === undefined) return undefined;
  let parsed: URL | undefined;
  try {
    parsed = new URL(origin);
  } catch {
    parsed = undefined;
  }
  if (parsed !== undefined && parsed.origin !== 'null') {
    if (allowed.has(parsed.origin)) return undefined;
    if (isLoopback(parsed.hostname)) return undefined;
  }
  return {
    header: 'origin',
    value: origin,
    reason: `Origin "${origin}" is a web page not served from this machine and not trusted`,
  };
}
