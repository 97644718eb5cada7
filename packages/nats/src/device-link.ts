import { delay, deviceOfflineError, HAL_ERROR_CODES, HalError } from '@hal/types';
import type { HalErrorCode, HalErrorPayload } from '@hal/types';
import { errors, headers as natsHeaders } from '@nats-io/transport-node';
import type { NatsConnection, Status, Subscription } from '@nats-io/transport-node';
import { z } from 'zod';
import { decodeMessage, encodeMessage } from './codec.js';
import { subjectFor } from './subjects.js';
import type { SubjectName } from './subjects.js';
import { ErrorReplySchema } from './messages.js';

export interface DeviceLinkOptions {
  /** The device addressed; undefined: the default device (the spec's bare subjects). */
  deviceId: string | undefined;
  /** This client's id, the envelope's sender. */
  clientId: string;
  /** Give up on one call after this long, ms (TIMEOUT). */
  callTimeoutMs: number;
  /** Wait this long for one attempt's reply before repeating it (same request id), ms. */
  attemptTimeoutMs: number;
  /** The device counts as gone after this long without a word from it, ms (NOT_CONNECTED). */
  offlineAfterMs: number;
}

/** How an offline error names the default device (the spec's bare subjects carry no id). */
export const DEFAULT_DEVICE_LABEL = '(default)';

function inChain(error: unknown, kind: abstract new (...args: never[]) => Error): boolean {
  for (let e: unknown = error; e instanceof Error; e = (e as Error).cause) {
    if (e instanceof kind) return true;
  }
  return false;
}

/** A HalError from the spec's error body (an unknown code becomes HARDWARE_ERROR, kept in details). */
export function errorFromPayload(payload: HalErrorPayload): HalError {
  const known = (HAL_ERROR_CODES as readonly string[]).includes(payload.code);
  const code = (known ? payload.code : 'HARDWARE_ERROR') as HalErrorCode;
  const details = { ...(payload.details ?? {}), ...(known ? {} : { remote_code: payload.code }) };
  return new HalError(code, payload.message, { details });
}

/** The reply schemas with the error reply beside them, built once per reply schema. */
const replyOrErrorSchemas = new WeakMap<z.ZodType, z.ZodType>();

/** `reply` or the spec's error reply: the reply first, as most answers are. */
function replyOrError(reply: z.ZodType): z.ZodType {
  let schema = replyOrErrorSchemas.get(reply);
  if (schema === undefined) {
    schema = z.union([reply, ErrorReplySchema]);
    replyOrErrorSchemas.set(reply, schema);
  }
  return schema;
}

/**
 * One client's link to one device over NATS: requests with retries that reuse the request id (so
 * the gateway runs each call once, however often it is repeated), and liveness from everything the
 * device sends. Every wait is bounded by `callTimeoutMs`.
 */
export class DeviceLink {
  /** The `device_id` of the last reply: who answered (the served id of the default device). */
  sender: string | undefined;
  /** When the device last said anything (0: never, so it counts as offline until it does). */
  #lastSeen = 0;
  #connected = true;
  readonly #subs: Subscription[] = [];
  readonly #status: AsyncIterator<Status>;

  constructor(
    readonly nc: NatsConnection,
    readonly options: DeviceLinkOptions,
  ) {
    this.#status = nc.status()[Symbol.asyncIterator]();
    void this.#watchStatus();
  }

  /** Listens to a stream of the device; every message also proves the device is alive. */
  listen(name: SubjectName, onData: (data: Uint8Array) => void): void {
    const sub = this.nc.subscribe(subjectFor(name, this.options.deviceId), {
      callback: (error, msg) => {
        if (error !== null) return;
        this.seen();
        onData(msg.data);
      },
    });
    this.#subs.push(sub);
  }

  seen(): void {
    this.#lastSeen = Date.now();
  }

  /** True when the device has said nothing for `offlineAfterMs` while our NATS link is up. */
  offline(): boolean {
    return this.#connected && Date.now() - this.#lastSeen > this.options.offlineAfterMs;
  }

  close(): void {
    for (const sub of this.#subs) sub.unsubscribe();
    this.#subs.length = 0;
    void this.#status.return?.();
  }

  async #watchStatus(): Promise<void> {
    for (;;) {
      const { value: status, done } = await this.#status.next();
      if (done === true) return;
      if (status.type === 'disconnect') this.#connected = false;
      if (status.type === 'reconnect') {
        this.#connected = true;
        this.seen(); // give the device the same grace to come back as we had
      }
    }
  }

  /**
   * Sends a request and returns the decoded reply payload; a reply carrying the spec's error body
   * rejects with that error. Repeats the same bytes until a reply, the device is gone
   * (NOT_CONNECTED) or `callTimeoutMs` runs out (TIMEOUT).
   */
  async request<S extends z.ZodType>(
    name: SubjectName,
    schema: string,
    payload: unknown,
    reply: S,
    options: { priority?: boolean; timeoutMs?: number } = {},
  ): Promise<z.output<S>> {
    const subject = subjectFor(name, this.options.deviceId);
    const data = encodeMessage(schema, this.options.clientId, [], payload);
    const deadline = Date.now() + (options.timeoutMs ?? this.options.callTimeoutMs);
    const headers = natsHeaders();
    headers.set('Priority', options.priority === true ? 'high' : 'normal');
    for (;;) {
      if (this.nc.isClosed()) throw new HalError('NOT_CONNECTED', 'the NATS connection is closed');
      const left = deadline - Date.now();
      if (left <= 0) {
        throw new HalError('TIMEOUT', `no reply on "${subject}" in time`, {
          details: { subject },
        });
      }
      try {
        const msg = await this.nc.request(subject, data, {
          timeout: Math.max(1, Math.min(left, this.options.attemptTimeoutMs)),
          headers,
        });
        this.seen();
        const envelope = decodeMessage(msg.data, replyOrError(reply));
        this.sender = envelope.device_id;
        const body = envelope.payload as unknown;
        // only a body with an `error` field can be the error reply: the common answer skips it
        if (typeof body === 'object' && body !== null && 'error' in body) {
          const failed = ErrorReplySchema.safeParse(body);
          if (failed.success) throw errorFromPayload(failed.data.error);
        }
        return body as z.output<S>;
      } catch (error) {
        if (error instanceof HalError) throw error;
        if (inChain(error, errors.ClosedConnectionError)) {
          throw new HalError('NOT_CONNECTED', 'the NATS connection is closed', { cause: error });
        }
        if (this.offline()) {
          // a device never heard from has not been waited for: say what was seen, claim no time
          const noOne = inChain(error, errors.NoRespondersError);
          const reason =
            this.#lastSeen === 0
              ? `it has not answered on "${subject}"${noOne ? ': no one serves it' : ''}`
              : `nothing from it for ${Date.now() - this.#lastSeen} ms`;
          throw deviceOfflineError(
            this.options.deviceId ?? DEFAULT_DEVICE_LABEL,
            reason,
            { subject },
            error,
          );
        }
        // No responders (a gateway restarting) or a lost reply: repeat after a short pause.
        if (inChain(error, errors.NoRespondersError)) await delay(50);
      }
    }
  }
}
