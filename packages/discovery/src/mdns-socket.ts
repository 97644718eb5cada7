// One place that opens bonjour-service, so that a socket error (port 5353 taken, no permission)
// becomes a rejected promise instead of an uncaught exception: bonjour-service leaves the
// multicast-dns 'error' event without a listener, and an EventEmitter throws on such an event.
import { EventEmitter } from 'node:events';
import { Bonjour } from 'bonjour-service';
import { HalError, errorMessage } from '@hal/types';

/** Where mDNS packets go: the standard 224.0.0.251:5353, on the default interface. */
export interface MdnsOptions {
  /**
   * The IPv4 address of the interface to send and join the group on. Default: the system's
   * choice (the default route's interface), which also reaches programs on this machine because
   * multicast loopback is on. Loopback (`lo`) itself has no multicast on Linux.
   */
  interface?: string;
  /** UDP port, default 5353 (another port only reaches programs told the same). */
  port?: number;
}

export interface MdnsHandle {
  bonjour: Bonjour;
  /** Rejects when the mDNS socket fails. */
  failed: Promise<never>;
  close(): Promise<void>;
}

export function openMdns(options: MdnsOptions = {}): MdnsHandle {
  let fail: (error: Error) => void = () => undefined;
  const failed = new Promise<never>((_, reject) => {
    fail = reject;
  });
  failed.catch(() => undefined); // observed by whoever races it
  const onError = (error: unknown) =>
    fail(
      new HalError('NOT_CONNECTED', `mDNS socket failed: ${errorMessage(error)}`, { cause: error }),
    );
  const bonjour = new Bonjour(
    {
      ...(options.interface === undefined ? {} : { interface: options.interface }),
      ...(options.port === undefined ? {} : { port: options.port }),
    },
    onError,
  );
  const socket = (bonjour as unknown as { server?: { mdns?: unknown } }).server?.mdns;
  if (socket instanceof EventEmitter) socket.on('error', onError);
  let closed = false;
  return {
    bonjour,
    failed,
    close: () =>
      new Promise<void>((resolve) => {
        if (closed) {
          resolve();
          return;
        }
        closed = true;
        bonjour.destroy(() => resolve());
      }),
  };
}
