import { HalError, errorMessage } from '@hal/types';
import { scoped } from '@hal/types';
import type { Logger, ScopedLogger } from '@hal/types';
import { boundaryOf, MultipartParser } from './multipart.js';

/** Options of {@link MjpegCamera}. */
export interface MjpegCameraOptions {
  /** The camera's base URL, e.g. `http://192.168.4.2`; the stream is `GET {url}/stream`. */
  url: string;
  /**
   * The camera's token (its `CAM_TOKEN`), sent as `Authorization: Bearer`; never logged. Default:
   * none, for a camera without a token.
   */
  token?: string;
  /** Wait this long after the stream ends or fails before reconnecting, ms. Default 1000. */
  reconnectDelayMs?: number;
  /** `captureFrame` waits this long for a first frame, ms. Default 5000. */
  frameTimeoutMs?: number;
  /**
   * A frame that arrived longer ago than this is stale: `captureFrame` waits for a newer one, ms.
   * Default 0: a frame that arrives after the call, so that a capture made after a motion never
   * shows the robot from before it (at the sketch's 10 frames a second, up to 100 ms more per
   * capture). A larger value trades that for speed: a frame up to that old, wherever the robot
   * was then.
   */
  maxFrameAgeMs?: number;
  /** The fetch implementation (a test seam). Default the global `fetch`. */
  fetch?: typeof fetch;
  logger?: Logger;
}

/** Counters of the camera reader. */
export interface MjpegStats {
  frames: number;
  connects: number;
  errors: number;
}

function isJpeg(bytes: Uint8Array): boolean {
  return bytes.length >= 4 && bytes[0] === 0xff && bytes[1] === 0xd8;
}

function toBase64(bytes: Uint8Array): string {
  const B = (globalThis as { Buffer?: { from(b: Uint8Array): { toString(e: string): string } } })
    .Buffer;
  if (B !== undefined) return B.from(bytes).toString('base64');
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary);
}

/**
 * Reads the ESP32-CAM's MJPEG stream (`GET /stream`, `multipart/x-mixed-replace`) in the
 * background, keeps the latest JPEG, and reconnects whenever the stream ends or fails.
 */
export class MjpegCamera {
  readonly #options: MjpegCameraOptions;
  readonly #log: ScopedLogger;
  readonly #fetch: typeof fetch;
  #latest: { jpeg: Uint8Array; at: number } | undefined;
  #waiters = new Set<() => void>();
  #abort: AbortController | undefined;
  #running = false;
  #loop: Promise<void> | undefined;
  #lastError: string | undefined;
  readonly stats: MjpegStats = { frames: 0, connects: 0, errors: 0 };

  constructor(options: MjpegCameraOptions) {
    this.#options = options;
    this.#log = scoped(options.logger ?? { log: () => undefined }, 'hal:physical:camera');
    this.#fetch = options.fetch ?? ((...args) => globalThis.fetch(...args));
  }

  /** Starts reading the stream in the background. */
  start(): void {
    if (this.#running) return;
    this.#running = true;
    this.#loop = this.#run();
  }

  /** Stops reading, closes the connection and cancels a pending reconnect; nothing is left running. */
  async stop(): Promise<void> {
    this.#running = false;
    this.#abort?.abort();
    for (const wake of this.#waiters) wake();
    await this.#loop;
    this.#loop = undefined;
  }

  /** Whether the reader is running (between {@link start} and {@link stop}). */
  get running(): boolean {
    return this.#running;
  }

  /** The latest JPEG and when it arrived (ms, `performance.now()`), if any. */
  latest(): { jpeg: Uint8Array; at: number } | undefined {
    return this.#latest;
  }

  /**
   * The next frame as a `data:image/jpeg;base64,...` URL: the first to arrive after the call
   * (or, with `maxFrameAgeMs`, the latest if it is no older than that). Rejects with NOT_READY when the reader is not running (it never
   * starts the stream itself: after {@link stop} nothing may open it again but {@link start}), and
   * with TIMEOUT when no frame comes in time.
   */
  async captureFrame(): Promise<string> {
    if (!this.#running) {
      throw new HalError('NOT_READY', 'the camera reader is not running; call start() first', {
        details: { url: this.#options.url },
      });
    }
    const maxAge = this.#options.maxFrameAgeMs ?? 0;
    const fresh = () =>
      maxAge > 0 && this.#latest !== undefined && performance.now() - this.#latest.at <= maxAge;
    if (!fresh()) {
      const timeoutMs = this.#options.frameTimeoutMs ?? 5000;
      await new Promise<void>((resolve, reject) => {
        const timer = setTimeout(() => {
          this.#waiters.delete(wake);
          const lastError = this.#lastError;
          reject(
            new HalError(
              'TIMEOUT',
              `no camera frame from ${this.#options.url} within ${timeoutMs} ms` +
                (lastError === undefined ? '' : ` (last error: ${lastError})`),
              { details: { url: this.#options.url, timeoutMs, lastError } },
            ),
          );
        }, timeoutMs);
        const wake = () => {
          clearTimeout(timer);
          this.#waiters.delete(wake);
          if (this.#running) resolve();
          else reject(new HalError('NOT_CONNECTED', 'the camera reader was stopped'));
        };
        this.#waiters.add(wake);
      });
    }
    const latest = this.#latest;
    if (latest === undefined) throw new HalError('TIMEOUT', 'no camera frame');
    return `data:image/jpeg;base64,${toBase64(latest.jpeg)}`;
  }

  async #run(): Promise<void> {
    const url = `${this.#options.url.replace(/\/+$/, '')}/stream`;
    while (this.#running) {
      this.#abort = new AbortController();
      try {
        const token = this.#options.token;
        const response = await this.#fetch(url, {
          signal: this.#abort.signal,
          ...(token !== undefined && { headers: { Authorization: `Bearer ${token}` } }),
        });
        const boundary = boundaryOf(response.headers.get('content-type'));
        if (!response.ok || response.body === null || boundary === undefined) {
          await response.body?.cancel().catch(() => undefined);
          throw new Error(
            `GET ${url}: ${response.status} ${response.headers.get('content-type') ?? 'no content type'}`,
          );
        }
        this.stats.connects += 1;
        this.#lastError = undefined;
        this.#log.debug('stream connected', { url });
        const parser = new MultipartParser(boundary);
        const reader = response.body.getReader();
        for (;;) {
          const { done, value } = await reader.read();
          if (done) break;
          for (const part of parser.push(value)) {
            if (!isJpeg(part)) continue;
            this.#latest = { jpeg: part, at: performance.now() };
            this.stats.frames += 1;
            for (const wake of this.#waiters) wake();
          }
        }
        this.#log.debug('stream ended', { url });
      } catch (error) {
        if (!this.#running) break;
        this.stats.errors += 1;
        this.#lastError = errorMessage(error);
        this.#log.debug('stream failed', { url, error: this.#lastError });
      }
      if (!this.#running) break;
      await this.#pause(this.#options.reconnectDelayMs ?? 1000);
    }
  }

  /** Waits before a reconnect; {@link stop} cuts the wait short, so no timer outlives it. */
  async #pause(ms: number): Promise<void> {
    await new Promise<void>((resolve) => {
      const wake = () => {
        clearTimeout(timer);
        this.#waiters.delete(wake);
        resolve();
      };
      const timer = setTimeout(wake, ms);
      this.#waiters.add(wake);
    });
  }
}
