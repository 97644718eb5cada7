import { HalError } from '@hal/types';
import { scoped } from '@hal/types';
import type {
  RequestOptions,
  Transport,
  TransportContext,
  TransportFactory,
  TransportStats,
} from './transport.js';
import { linkOpenError, ReplyMatcher, requestDefaults } from './transport.js';

/** The robot's UDP port. */
export const DEFAULT_UDP_PORT = 4210;

/** Options of {@link udpTransport}. */
export interface UdpTransportOptions {
  /** The robot's IP address or host name. */
  host: string;
  /** The robot's UDP port. Default 4210. */
  port?: number;
  /** Wait for a reply this long before resending, ms. Default 2000. */
  timeoutMs?: number;
  /** Send each request at most this many times. Default 3. */
  attempts?: number;
}

/**
 * A connected socket hears the robot's ICMP "port unreachable" (a robot restarting) as
 * ECONNREFUSED, on a receive (Linux) or on the next send. It is a lost datagram: the attempt still
 * waits its timeout, as it would without the connection.
 */
function isUnreachable(error: Error): boolean {
  return (error as NodeJS.ErrnoException).code === 'ECONNREFUSED';
}

/** A request's options over the transport's own: a new object only when each side sets some. */
function overDefaults(
  options: RequestOptions | undefined,
  defaults: RequestOptions,
): RequestOptions {
  if (options === undefined) return defaults;
  const complete = options.attempts !== undefined && options.timeoutMs !== undefined;
  return complete || (defaults.attempts === undefined && defaults.timeoutMs === undefined)
    ? options
    : { ...defaults, ...options };
}

/** A connected UDP transport. */
export interface UdpTransport extends Transport {
  readonly type: 'udp';
  /** The local port the socket is bound to. */
  readonly localPort: number;
}

/**
 * WiFi link: one JSON message per datagram to the robot's port 4210, replies matched to requests
 * by their echoed `seq`. The socket is connected to the robot's address and port, so the kernel
 * delivers nothing else to it: a datagram from any other host or port (a forged "move done"
 * reply from someone on the LAN) never reaches the HAL. `node:dgram` is loaded on connect, so
 * importing the package is safe in a browser bundle.
 */
export function udpTransport(options: UdpTransportOptions): TransportFactory<'udp'> {
  if (typeof options.host !== 'string' || options.host.length === 0) {
    throw new HalError('INVALID_PARAMETER', '"host" must be a non-empty string');
  }
  const port = options.port ?? DEFAULT_UDP_PORT;
  if (!Number.isInteger(port) || port < 1 || port > 65535) {
    throw new HalError('INVALID_PARAMETER', `"port" must be an integer 1..65535, got ${port}`);
  }
  return {
    type: 'udp',
    connect: async (context: TransportContext): Promise<UdpTransport> => {
      const dgram = await import('node:dgram');
      const { isIPv6 } = await import('node:net');
      const log = scoped(context.logger, 'hal:physical:udp');
      const socket = dgram.createSocket(isIPv6(options.host) ? 'udp6' : 'udp4');
      const matcher = new ReplyMatcher();
      const defaults = requestDefaults(options);
      let closed = false;

      // the socket is connected: every datagram here comes from the robot's address and port
      socket.on('message', (message) => {
        const result = context.decode(
          new Uint8Array(message.buffer, message.byteOffset, message.length),
        );
        if (!matcher.deliver(result)) {
          log.debug(
            'datagram dropped',
            result.ok ? { seq: result.reply.seq } : { error: result.error.message },
          );
        }
      });
      socket.on('error', (error) => {
        if (isUnreachable(error)) log.debug('robot port unreachable; as a lost datagram');
        else log.warn('socket error', { error: error.message });
      });
      await new Promise<void>((resolve, reject) => {
        socket.once('error', reject);
        socket.bind(0, () => {
          socket.off('error', reject);
          resolve();
        });
      });
      try {
        await new Promise<void>((resolve, reject) => {
          // connect() reports a failed name lookup through its callback
          socket.connect(port, options.host, (error?: Error) =>
            error ? reject(error) : resolve(),
          );
        });
      } catch (cause) {
        socket.close();
        throw linkOpenError(`cannot reach the robot at ${options.host}:${port}`, cause, {
          host: options.host,
          port,
        });
      }
      const localPort = socket.address().port;
      const robot = socket.remoteAddress();
      log.debug('connected', { localPort, host: options.host, address: robot.address, port });

      return {
        type: 'udp',
        localPort,
        request: (seq, bytes, requestOptions) => {
          let resend = false;
          return matcher.requestWith(
            seq,
            (done) => {
              if (closed) {
                done(new HalError('NOT_CONNECTED', 'the UDP transport is closed'));
                return;
              }
              if (!resend) {
                // the first send reports nothing: node:dgram's send callback costs about half a
                // kilobyte of allocation per request, and a datagram that failed to go out is a
                // lost one, which this attempt's timeout finds; the resends report their errors
                resend = true;
                socket.send(bytes);
                done();
                return;
              }
              socket.send(bytes, (error) =>
                error && !isUnreachable(error) ? done(error) : done(),
              );
            },
            overDefaults(requestOptions, defaults),
          );
        },
        stats: (): TransportStats => matcher.stats(),
        close: async () => {
          if (closed) return;
          closed = true;
          matcher.close();
          await new Promise<void>((resolve) => socket.close(() => resolve()));
        },
      };
    },
  };
}
