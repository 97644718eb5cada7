import { HalError } from '@hal/types';
import { scoped } from '@hal/types';
import { encodeFrame } from '../serial/frame.js';
import type { FrameType } from '../serial/frame.js';
import { FrameDecoder } from '../serial/frame-decoder.js';
import type {
  RequestOptions,
  SerialLinkStats,
  Transport,
  TransportContext,
  TransportFactory,
  TransportStats,
} from './transport.js';
import {
  DEFAULT_ATTEMPTS,
  DEFAULT_REPLY_TIMEOUT_MS,
  linkOpenError,
  ReplyMatcher,
} from './transport.js';

/** A partial frame with no further byte for this long is abandoned (protocol 1.0, section 7). */
export const PARTIAL_FRAME_TIMEOUT_MS = 200;

/** The few members of a `serialport` port the transport uses (a `SerialPortMock` is one too). */
export interface SerialPortLike {
  write(data: Uint8Array, callback?: (error?: Error | null) => void): unknown;
  on(event: 'data', listener: (chunk: Uint8Array) => void): unknown;
  on(event: 'error', listener: (error: Error) => void): unknown;
  on(event: 'close', listener: () => void): unknown;
  close(callback?: (error?: Error | null) => void): unknown;
  readonly isOpen: boolean;
}

/** Opens a port; the default loads `serialport` on first use. */
export type SerialPortOpener = (path: string, baudRate: number) => Promise<SerialPortLike>;

/** Options of {@link serialTransport}. */
export interface SerialTransportOptions {
  /** Serial device, e.g. `/dev/ttyUSB0` or the emulator's pseudo-terminal. */
  path: string;
  /** Bits/s. Default 115200. */
  baudRate?: number;
  /** Wait this long for an ACK, and then for the reply, before resending, ms. Default 2000. */
  timeoutMs?: number;
  /** Send each frame, and each request, at most this many times. Default 3. */
  attempts?: number;
  /** Opens the port (a test seam). Default: `serialport`'s `SerialPort`, loaded on first use. */
  open?: SerialPortOpener;
}

/** A connected serial transport. */
export interface SerialTransport extends Transport {
  readonly type: 'serial';
  /** Link-level statistics (frames, ACKs, checksum errors, resyncs). */
  linkStats(): SerialLinkStats;
}

/** Opens a serial port with `serialport` (loaded on first use; Node only). */
export const openSerialPort: SerialPortOpener = async (path, baudRate) => {
  // Loaded here, on first use, so that nothing native reaches a browser bundle.
  const { SerialPort } = await import('serialport');
  return await new Promise<SerialPortLike>((resolve, reject) => {
    const port = new SerialPort({ path, baudRate, autoOpen: false });
    port.open((error) => (error ? reject(error) : resolve(port)));
  });
};

/**
 * Serial link: each message travels in a CRC-16/CCITT-FALSE frame, is acknowledged, and is resent
 * (same link `seq`) when its ACK does not come in time; replies are matched to requests by their
 * echoed `seq`, and a request is resent as a new frame (same bytes) when its reply is lost.
 */
export function serialTransport(options: SerialTransportOptions): TransportFactory<'serial'> {
  if (typeof options.path !== 'string' || options.path.length === 0) {
    throw new HalError('INVALID_PARAMETER', '"path" must be a non-empty string');
  }
  const baudRate = options.baudRate ?? 115200;
  if (!Number.isInteger(baudRate) || baudRate <= 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"baudRate" must be a positive integer, got ${baudRate}`,
    );
  }
  const timeoutMs = options.timeoutMs ?? DEFAULT_REPLY_TIMEOUT_MS;
  const attempts = options.attempts ?? DEFAULT_ATTEMPTS;
  const open = options.open ?? openSerialPort;

  return {
    type: 'serial',
    connect: async (context: TransportContext): Promise<SerialTransport> => {
      const log = scoped(context.logger, 'hal:physical:serial');
      let port: SerialPortLike;
      try {
        port = await open(options.path, baudRate);
      } catch (cause) {
        throw linkOpenError(`cannot open serial port ${options.path}`, cause, {
          path: options.path,
        });
      }
      const matcher = new ReplyMatcher();
      const link: SerialLinkStats = {
        framesSent: 0,
        framesReceived: 0,
        acksSent: 0,
        acksReceived: 0,
        frameRetries: 0,
        frameTimeouts: 0,
        checksumErrors: 0,
        resyncBytes: 0,
        duplicateFrames: 0,
      };
      let closed = false;
      let txSeq = Math.floor(Math.random() * 0x10000);
      let lastDelivered: number | undefined;
      let awaitingAck: { seq: number; acked: () => void; abort: () => void } | undefined;
      let partialTimer: ReturnType<typeof setTimeout> | undefined;
      let chain: Promise<unknown> = Promise.resolve();

      let reopening: Promise<void> | undefined;
      /** Opens the port again after it went away (a USB cable pulled, the board reset). */
      const reopen = async (): Promise<void> => {
        reopening ??= (async () => {
          try {
            const fresh = await open(options.path, baudRate);
            if (closed) {
              fresh.close();
              return;
            }
            port = fresh;
            attach(fresh);
            log.info('serial port reopened', { path: options.path });
          } finally {
            reopening = undefined;
          }
        })();
        return reopening;
      };

      const write = async (bytes: Uint8Array): Promise<void> => {
        if (!closed && !port.isOpen) {
          await reopen().catch((cause: unknown) => {
            throw new HalError('NOT_CONNECTED', `cannot reopen serial port ${options.path}`, {
              cause,
            });
          });
        }
        return new Promise<void>((resolve, reject) => {
          if (closed || !port.isOpen) {
            reject(new HalError('NOT_CONNECTED', 'the serial port is closed'));
            return;
          }
          port.write(bytes, (error) => (error ? reject(error) : resolve()));
        });
      };

      const onFrame = (type: FrameType, seq: number, payload: Uint8Array): void => {
        if (type === 'ack') {
          link.acksReceived += 1;
          if (awaitingAck !== undefined && awaitingAck.seq === seq) awaitingAck.acked();
          return;
        }
        link.framesReceived += 1;
        link.acksSent += 1;
        write(encodeFrame({ type: 'ack', seq, payload: new Uint8Array(0) })).catch(
          (error: unknown) => log.debug('ACK not written', { error: String(error) }),
        );
        if (seq === lastDelivered) {
          link.duplicateFrames += 1;
          return;
        }
        lastDelivered = seq;
        // the payload is a view of the port's chunk: decoded here at once, nothing keeps it
        const result = context.decode(payload);
        if (!matcher.deliver(result)) {
          log.debug(
            'frame payload dropped',
            result.ok ? { seq: result.reply.seq } : { error: result.error.message },
          );
        }
      };
      const decoder = new FrameDecoder({
        onFrame,
        onGarbage: (dropped) => {
          link.resyncBytes += dropped;
        },
        onError: (error, dropped) => {
          link.resyncBytes += dropped;
          if (error === 'bad_crc') link.checksumErrors += 1;
        },
        onOversize: (length) => log.debug('oversize frame header', { length }),
      });

      const attach = (target: SerialPortLike): void => {
        target.on('data', (chunk) => {
          if (target !== port) return;
          clearTimeout(partialTimer);
          decoder.push(chunk); // a Buffer is a Uint8Array: no copy
          if (decoder.pending > 0) {
            partialTimer = setTimeout(function abandon() {
              decoder.abandon();
              if (decoder.pending > 0) partialTimer = setTimeout(abandon, PARTIAL_FRAME_TIMEOUT_MS);
            }, PARTIAL_FRAME_TIMEOUT_MS);
          }
        });
        target.on('error', (error) => log.warn('serial port error', { error: error.message }));
        target.on('close', () => {
          if (!closed) log.warn('serial port closed; it is reopened on the next send');
        });
      };
      attach(port);

      /** Sends one DATA frame and waits for its ACK, resending the same frame up to `attempts` times. */
      const sendFrame = async (payload: Uint8Array): Promise<void> => {
        const seq = txSeq;
        txSeq = (txSeq + 1) & 0xffff;
        const frame = encodeFrame({ type: 'data', seq, payload });
        for (let attempt = 1; attempt <= attempts; attempt++) {
          if (closed) throw new HalError('NOT_CONNECTED', 'the serial port is closed');
          if (attempt > 1) link.frameRetries += 1;
          let timer: ReturnType<typeof setTimeout> | undefined;
          const acked = new Promise<boolean>((resolve) => {
            awaitingAck = { seq, acked: () => resolve(true), abort: () => resolve(false) };
            timer = setTimeout(() => resolve(false), timeoutMs);
          });
          try {
            link.framesSent += 1;
            await write(frame);
            if (await acked) return;
          } finally {
            clearTimeout(timer);
            awaitingAck = undefined;
          }
        }
        link.frameTimeouts += 1;
        throw new HalError('TIMEOUT', `no ACK for frame ${seq} after ${attempts} attempts`);
      };

      const defaults: RequestOptions = { timeoutMs, attempts };
      return {
        type: 'serial',
        request: (seq, bytes, requestOptions) =>
          matcher.request(
            seq,
            () => {
              // one DATA frame outstanding at a time
              const sent = chain.then(() => sendFrame(bytes));
              chain = sent.catch(() => undefined);
              return sent;
            },
            { ...defaults, ...requestOptions },
          ),
        stats: (): TransportStats => matcher.stats(),
        linkStats: () => ({ ...link }),
        close: async () => {
          if (closed) return;
          closed = true;
          clearTimeout(partialTimer);
          awaitingAck?.abort();
          matcher.close();
          await new Promise<void>((resolve) => {
            if (!port.isOpen) resolve();
            else port.close(() => resolve());
          });
        },
      };
    },
  };
}
