import { subjectFor } from '@hal/nats';
import type { SubjectName } from '@hal/nats';
import { buildSubject, makeEnvelope } from '@hal/types';
import { errors, headers } from '@nats-io/transport-node';
import type { NatsConnection, Subscription } from '@nats-io/transport-node';

/** How a request ended, with the time it took (ms, measured around the NATS request). */
export type Outcome =
  | { kind: 'reply'; data: Uint8Array; latencyMs: number }
  | { kind: 'no-responders'; latencyMs: number }
  | { kind: 'timeout'; latencyMs: number };

const encoder = new TextEncoder();

function inChain(error: unknown, type: abstract new (...args: never[]) => Error): boolean {
  let e: unknown = error;
  while (e instanceof Error) {
    if (e instanceof type) return true;
    e = (e as { cause?: unknown }).cause;
  }
  return false;
}

/**
 * The raw NATS side of a spec-only client: subjects for the device under test (the spec's bare
 * subjects for the default device, `hal.v1.dev.{device}...` for one of a fleet), envelopes sent
 * as `clientId`, requests that report no-responders and timeouts as outcomes, not throws.
 */
export class DeviceWire {
  readonly #subs: Subscription[] = [];

  constructor(
    readonly nc: NatsConnection,
    readonly device: string | undefined,
    readonly clientId: string,
  ) {}

  subject(name: SubjectName): string {
    return subjectFor(name, this.device);
  }

  /** A subject the spec does not define, under the device's address. */
  unknownSubject(): string {
    return buildSubject({
      device: this.device,
      domain: 'motor',
      type: 'differential',
      action: 'warp',
    });
  }

  /** An envelope from this client around `payload`. */
  envelope(schema: string, payload: unknown): Uint8Array {
    return encoder.encode(
      JSON.stringify(makeEnvelope({ schema, device_id: this.clientId }, payload)),
    );
  }

  /** A bare spec payload, as the spec's own example driver reads it: no envelope around it. */
  bare(payload: unknown): Uint8Array {
    return encoder.encode(JSON.stringify(payload));
  }

  async request(
    subject: string,
    data: Uint8Array,
    options: { timeoutMs: number; priority?: 'high' },
  ): Promise<Outcome> {
    const started = performance.now();
    const h = options.priority === undefined ? undefined : headers();
    h?.set('Priority', options.priority ?? '');
    try {
      const msg = await this.nc.request(subject, data, {
        timeout: options.timeoutMs,
        ...(h === undefined ? {} : { headers: h }),
      });
      return { kind: 'reply', data: msg.data, latencyMs: performance.now() - started };
    } catch (error) {
      const latencyMs = performance.now() - started;
      if (inChain(error, errors.NoRespondersError)) return { kind: 'no-responders', latencyMs };
      if (inChain(error, errors.TimeoutError)) return { kind: 'timeout', latencyMs };
      throw error;
    }
  }

  publish(subject: string, data: Uint8Array): void {
    this.nc.publish(subject, data);
  }

  /** Calls `onMessage` with every message on `subject` and when it arrived (performance.now()). */
  subscribe(subject: string, onMessage: (data: Uint8Array, atMs: number) => void): void {
    this.#subs.push(
      this.nc.subscribe(subject, {
        callback: (error, msg) => {
          if (error === null) onMessage(msg.data, performance.now());
        },
      }),
    );
  }

  async flush(): Promise<void> {
    await this.nc.flush();
  }

  close(): void {
    for (const sub of this.#subs.splice(0)) sub.unsubscribe();
  }
}
