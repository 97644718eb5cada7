import { HalError } from '@hal/types';
import type { Socket } from 'node:dgram';
import { createAuthenticator } from '../protocol/auth.js';
import { MockRobot } from './mock-robot.js';
import type { MockRobotOptions } from './mock-robot.js';

/** Options of {@link MockUdpRobot.start}. */
export interface MockUdpRobotOptions extends Omit<MockRobotOptions, 'auth'> {
  /**
   * The pre-shared key as hex (1..64 bytes), as a HAL's `connection.key`: every message in both
   * directions is MACed. Without it the robot runs unauthenticated (`hello` says `auth: "none"`).
   */
  key?: string;
  /** The IPv4 address to listen on. Default `127.0.0.1`. */
  host?: string;
  /** The UDP port. Default 0: a free one, chosen by the system (read it from `port`). */
  port?: number;
}

/** The `connection` of a HALConfig that reaches a {@link MockUdpRobot}. */
export interface MockUdpConnection {
  type: 'wifi';
  host: string;
  udpPort: number;
  key?: string;
}

/**
 * A {@link MockRobot} on a real UDP socket: the robot of `@hal/physical/testing`, reached over the
 * wire as the firmware is (one message per datagram, each reply sent to the address and port of
 * the request it answers), so `PhysicalHAL` and anything else that speaks the protocol drive it
 * through their own UDP transport. Every datagram goes to the in-process robot's `receive`; the
 * test helpers (`dropReplies`, `dropRequests`, `unresponsive`, `restart()`, `requests`,
 * `position`...) are the same. `close()` releases the port.
 *
 * ```ts
 * const robot = await MockUdpRobot.start(); // 127.0.0.1, a free port
 * const hal = new PhysicalHAL({ mode: 'physical', deviceId: 'cube', connection: robot.connection });
 * ```
 */
export class MockUdpRobot extends MockRobot {
  /** The address it listens on. */
  readonly host: string;
  /** The UDP port it listens on. */
  readonly port: number;
  /** The key it was given (hex), if any. */
  readonly key: string | undefined;
  readonly #socket: Socket;
  #closed: Promise<void> | undefined;

  private constructor(
    socket: Socket,
    host: string,
    key: string | undefined,
    robot: MockRobotOptions,
  ) {
    super(robot);
    this.#socket = socket;
    this.host = host;
    this.port = socket.address().port;
    this.key = key;
    socket.on('message', (message, from) => {
      const reply = this.receive(
        new Uint8Array(message.buffer, message.byteOffset, message.length),
      );
      // a reply that cannot go out is a lost datagram, as on the board
      if (reply !== undefined) socket.send(reply, from.port, from.address, () => undefined);
    });
  }

  /**
   * Starts a robot listening on `host:port` (default 127.0.0.1 and a free port). Rejects with
   * INVALID_PARAMETER for a bad key, host or port, and with NOT_CONNECTED when the socket cannot
   * be bound (the port in use: the system's error is the cause).
   */
  static async start(options: MockUdpRobotOptions = {}): Promise<MockUdpRobot> {
    const { key, host = '127.0.0.1', port = 0, ...robot } = options;
    const { isIPv4 } = await import('node:net');
    if (!isIPv4(host)) {
      throw new HalError('INVALID_PARAMETER', `"host" must be an IPv4 address, got "${host}"`, {
        details: { parameter: 'host' },
      });
    }
    if (!Number.isInteger(port) || port < 0 || port > 65_535) {
      throw new HalError('INVALID_PARAMETER', `"port" must be an integer 0..65535, got ${port}`, {
        details: { parameter: 'port' },
      });
    }
    const auth = key === undefined ? undefined : await createAuthenticator(key);
    const dgram = await import('node:dgram');
    const socket = dgram.createSocket('udp4');
    try {
      await new Promise<void>((resolve, reject) => {
        socket.once('error', reject);
        socket.bind(port, host, () => {
          socket.off('error', reject);
          resolve();
        });
      });
    } catch (cause) {
      socket.close();
      const code = (cause as NodeJS.ErrnoException).code ?? 'unknown error';
      throw new HalError('NOT_CONNECTED', `cannot listen on udp ${host}:${port} (${code})`, {
        cause,
        details: { host, port },
      });
    }
    // an error after the bind (none is expected on a bound UDP socket) loses a datagram, no more
    socket.on('error', () => undefined);
    return new MockUdpRobot(socket, host, key, auth === undefined ? robot : { ...robot, auth });
  }

  /** The HALConfig `connection` that reaches this robot (with its key, when it has one). */
  get connection(): MockUdpConnection {
    const connection: MockUdpConnection = { type: 'wifi', host: this.host, udpPort: this.port };
    if (this.key !== undefined) connection.key = this.key;
    return connection;
  }

  /** Stops listening and releases the port. Idempotent. */
  close(): Promise<void> {
    this.#closed ??= new Promise<void>((resolve) => this.#socket.close(() => resolve()));
    return this.#closed;
  }
}
