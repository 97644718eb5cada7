import { HalError } from '@hal/types';
import type { Transport, TransportFactory } from '../transport/transport.js';
import { ReplyMatcher, requestDefaults } from '../transport/transport.js';

/** Options of {@link MockRobot.transport}. */
export interface MockTransportOptions {
  /** Deliver each reply after this many ms. Default 0 (next macrotask). */
  latencyMs?: number;
  timeoutMs?: number;
  attempts?: number;
}

/**
 * A transport to an in-process robot: each request's bytes go to `receive` a macrotask (or
 * `latencyMs`) later, and its reply, if any, back through the real codec.
 */
export function mockTransport(
  receive: (bytes: Uint8Array) => Uint8Array | undefined,
  options: MockTransportOptions = {},
): TransportFactory<'mock'> {
  return {
    type: 'mock',
    connect: async (context): Promise<Transport> => {
      const matcher = new ReplyMatcher();
      let closed = false;
      const defaults = requestDefaults(options);
      return {
        type: 'mock',
        request: (seq, bytes, requestOptions) =>
          matcher.request(
            seq,
            async () => {
              if (closed) throw new HalError('NOT_CONNECTED', 'the mock transport is closed');
              const copy = bytes.slice();
              setTimeout(() => {
                if (closed) return;
                const reply = receive(copy);
                if (reply !== undefined) matcher.deliver(context.decode(reply));
              }, options.latencyMs ?? 0);
            },
            { ...defaults, ...requestOptions },
          ),
        stats: () => matcher.stats(),
        close: async () => {
          closed = true;
          matcher.close();
        },
      };
    },
  };
}
