/*
 * A streaming parser for `multipart/x-mixed-replace` bodies (the ESP32-CAM's `GET /stream`): feed
 * it chunks as they arrive, get back each part's body. A part with `Content-Length` is cut at that
 * length; one without ends at the next boundary.
 */

const CRLF2 = new Uint8Array([13, 10, 13, 10]);
const encoder = new TextEncoder();
const decoder = new TextDecoder();

function indexOf(haystack: Uint8Array, needle: Uint8Array, from = 0): number {
  const first = needle[0];
  outer: for (
    let i = haystack.indexOf(first ?? 0, from);
    i >= 0 && i + needle.length <= haystack.length;
    i = haystack.indexOf(first ?? 0, i + 1)
  ) {
    for (let j = 1; j < needle.length; j++) if (haystack[i + j] !== needle[j]) continue outer;
    return i;
  }
  return -1;
}

/** The boundary of a `multipart/...; boundary=...` content type, or undefined. */
export function boundaryOf(contentType: string | null): string | undefined {
  if (contentType === null || !/^multipart\//i.test(contentType.trim())) return undefined;
  const match = /boundary=("([^"]+)"|[^;\s]+)/i.exec(contentType);
  const raw = match?.[2] ?? match?.[1];
  return raw === undefined ? undefined : raw.replace(/^--/, '');
}

/** Splits a multipart stream into part bodies. */
export class MultipartParser {
  readonly #delimiter: Uint8Array;
  readonly #maxPartBytes: number;
  #buffer = new Uint8Array(0);
  /** Parts dropped because they were larger than the limit. */
  oversized = 0;

  /** `boundary` without the leading dashes; parts larger than `maxPartBytes` are dropped. */
  constructor(boundary: string, maxPartBytes = 4 * 1024 * 1024) {
    this.#delimiter = encoder.encode(`--${boundary}`);
    this.#maxPartBytes = maxPartBytes;
  }

  push(chunk: Uint8Array): Uint8Array[] {
    const joined = new Uint8Array(this.#buffer.length + chunk.length);
    joined.set(this.#buffer);
    joined.set(chunk, this.#buffer.length);
    let buf = joined;
    const parts: Uint8Array[] = [];
    for (;;) {
      const start = indexOf(buf, this.#delimiter);
      if (start < 0) {
        // keep a tail that may hold the start of a delimiter
        buf = buf.subarray(Math.max(0, buf.length - this.#delimiter.length));
        break;
      }
      const headersAt = start + this.#delimiter.length;
      const headersEnd = indexOf(buf, CRLF2, headersAt);
      if (headersEnd < 0) {
        buf = buf.subarray(start);
        if (buf.length > 16 * 1024) buf = buf.subarray(1); // a runaway header block
        break;
      }
      const headers = decoder.decode(buf.subarray(headersAt, headersEnd));
      const bodyAt = headersEnd + CRLF2.length;
      const lengthMatch = /content-length:\s*(\d+)/i.exec(headers);
      let bodyEnd: number;
      if (lengthMatch?.[1] !== undefined) {
        const length = Number(lengthMatch[1]);
        if (length > this.#maxPartBytes) {
          this.oversized += 1;
          buf = buf.subarray(bodyAt);
          continue;
        }
        if (buf.length < bodyAt + length) {
          buf = buf.subarray(start);
          break;
        }
        bodyEnd = bodyAt + length;
      } else {
        const next = indexOf(buf, this.#delimiter, bodyAt);
        if (next < 0) {
          if (buf.length - bodyAt > this.#maxPartBytes) {
            this.oversized += 1;
            buf = buf.subarray(bodyAt);
            continue;
          }
          buf = buf.subarray(start);
          break;
        }
        bodyEnd = next;
        // the CRLF before a delimiter belongs to the delimiter
        if (buf[bodyEnd - 2] === 13 && buf[bodyEnd - 1] === 10) bodyEnd -= 2;
      }
      parts.push(buf.slice(bodyAt, bodyEnd));
      buf = buf.subarray(bodyEnd);
    }
    this.#buffer = buf.slice();
    return parts;
  }
}
