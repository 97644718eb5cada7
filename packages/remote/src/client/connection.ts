// One client link to a HAL server: the socket, the server's hello, requests matched to replies by
// id (each with a timeout), heartbeats, the cached state, and reconnection.
import { HalError } from '@hal/types';
import type { HalErrorCode, Pose, SafetyStatus } from '@hal/types';
import { scoped } from '@hal/types';
import type { Logger, LogLevel } from '@hal/types';
import { MESSAGE_SCHEMAS, decodeMessage, encodeArgs, encodeMessage } from '../protocol.js';
import type { HelloPayload, MessageSchema, Role } from '../protocol.js';
import { OPEN, resolveWebSocket } from './websocket.js';
import type { WebSocketConstructor, WebSocketLike } from './websocket.js';

const NS = 'hal:remote:client';

interface Pending {
  resolve: (value: unknown) => void;
  reject: (error: HalError) => void;
  timer: ReturnType<typeof setTimeout>;
}

export interface ConnectionOptions {
  url: string;
  token: string | undefined;
  WebSocket: WebSocketConstructor | undefined;
  clientId: string;
  /** Ask the server never to make this client the controller. */
  watchOnly: boolean;
  connectTimeoutMs: number;
  reconnect: boolean;
  reconnectDelayMs: number;
  logger: Logger;
  /** Called after every (re)connection, once the hello is in. */
  onConnected: (hello: HelloPayload) => void;
}

/** The text of a WebSocket error event (`ws` gives a message; a browser gives nothing). */
function errorText(event: unknown): string | undefined {
  if (typeof event !== 'object' || event === null) return undefined;
  const { message, error } = event as { message?: unknown; error?: unknown };
  if (typeof message === 'string' && message !== '') return message;
  if (error instanceof Error) return error.message;
  return undefined;
}

export class Connection {
  hello: HelloPayload | undefined;
  role: Role = 'watcher';
  safety: SafetyStatus | undefined;
  pose: Pose | null = null;
  moving = false;
  readonly roleListeners = new Set<(role: Role, reason: string) => void>();

  #socket: WebSocketLike | undefined;
  #pending = new Map<string, Pending>();
  #nextId = 1;
  #heartbeat: ReturnType<typeof setInterval> | undefined;
  #reconnectTimer: ReturnType<typeof setTimeout> | undefined;
  #wanted = false;
  #delay: number;
  readonly #options: ConnectionOptions;

  constructor(options: ConnectionOptions) {
    this.#options = options;
    this.#delay = options.reconnectDelayMs;
  }

  get connected(): boolean {
    return this.hello !== undefined && this.#socket?.readyState === OPEN;
  }

  /** Connects and waits for the hello; rejects NOT_CONNECTED (or TIMEOUT) if that fails. */
  async open(): Promise<void> {
    this.#wanted = true;
    await this.#connect();
  }

  /** Closes the link for good (until the next open()); pending calls fail NOT_CONNECTED. */
  close(): void {
    this.#wanted = false;
    clearTimeout(this.#reconnectTimer);
    this.#teardown('closed by the client');
  }

  /** Sends a message (false if the link is down). */
  send<K extends MessageSchema>(
    schema: K,
    payload: Parameters<typeof encodeMessage<K>>[2],
  ): boolean {
    const socket = this.#socket;
    if (socket === undefined || socket.readyState !== OPEN) return false;
    socket.send(encodeMessage(schema, { deviceId: this.#options.clientId }, payload));
    return true;
  }

  /** Runs a call on the server and resolves with its reply's value; rejects with a HalError. */
  request(call: string, args: readonly unknown[], timeoutMs: number): Promise<unknown> {
    if (!this.connected) {
      return Promise.reject(new HalError('NOT_CONNECTED', `not connected to ${this.#options.url}`));
    }
    const id = String(this.#nextId++);
    return new Promise<unknown>((resolve, reject) => {
      const timer = setTimeout(() => {
        this.#pending.delete(id);
        reject(new HalError('TIMEOUT', `no reply to "${call}" within ${timeoutMs} ms`));
      }, timeoutMs);
      this.#pending.set(id, { resolve, reject, timer });
      const sent =
        call === 'take_control'
          ? this.send(MESSAGE_SCHEMAS.takeControl, { id })
          : this.send(MESSAGE_SCHEMAS.call, { id, call, args: encodeArgs(args) });
      if (!sent) this.#settle(id, new HalError('NOT_CONNECTED', 'the link went down'));
    });
  }

  #log(level: LogLevel, message: string, fields?: Record<string, unknown>): void {
    scoped(this.#options.logger, NS)[level](message, fields);
  }

  async #connect(): Promise<void> {
    const { ctor, headers } = await resolveWebSocket(this.#options.WebSocket);
    const token = this.#options.token;
    let url = this.#options.url;
    if (this.#options.watchOnly) {
      const parsed = new URL(url);
      parsed.searchParams.set('role', 'watch');
      url = parsed.toString();
    }
    let socket: WebSocketLike;
    try {
      if (token !== undefined && headers) {
        socket = new ctor(url, undefined, { headers: { authorization: `Bearer ${token}` } });
      } else {
        if (token !== undefined) {
          const parsed = new URL(url);
          parsed.searchParams.set('token', token);
          url = parsed.toString();
        }
        socket = new ctor(url);
      }
    } catch (e) {
      throw new HalError('NOT_CONNECTED', `cannot connect to ${this.#options.url}: ${String(e)}`, {
        cause: e,
      });
    }
    this.#socket = socket;
    await new Promise<void>((resolve, reject) => {
      const timer = setTimeout(() => {
        fail(
          new HalError(
            'TIMEOUT',
            `no hello from ${this.#options.url} within ${this.#options.connectTimeoutMs} ms`,
          ),
        );
      }, this.#options.connectTimeoutMs);
      const fail = (error: HalError) => {
        clearTimeout(timer);
        socket.onclose = null;
        socket.onmessage = null;
        socket.close();
        if (this.#socket === socket) this.#socket = undefined;
        reject(error);
      };
      let refusal: string | undefined;
      socket.onerror = (event) => {
        refusal = errorText(event);
      };
      socket.onclose = (event) => fail(this.#closedBeforeHello(event, refusal));
      socket.onmessage = (event) => {
        this.#onMessage(event.data);
        if (this.hello === undefined) return;
        clearTimeout(timer);
        socket.onclose = (closed) => this.#onClose(socket, closed.code, closed.reason);
        resolve();
      };
    });
    const hello = this.hello as HelloPayload | undefined;
    if (hello === undefined) return;
    this.#delay = this.#options.reconnectDelayMs;
    const every = Math.max(50, hello.heartbeat_timeout_ms / 4);
    clearInterval(this.#heartbeat);
    this.#heartbeat = setInterval(() => this.send(MESSAGE_SCHEMAS.heartbeat, {}), every);
    this.#options.onConnected(hello);
  }

  /**
   * Why the socket closed before the server's hello. `ws` reports the HTTP status of a refused
   * upgrade ("Unexpected server response: 401"): a refused token (401), or an Origin or Host the
   * server does not trust (403), is AUTH_FAILED, not a dead server.
   * A browser's WebSocket hides the status, so there the message names both causes.
   */
  #closedBeforeHello(event: { code: number; reason: string }, refusal: string | undefined) {
    const url = this.#options.url;
    const status = /Unexpected server response: (\d{3})/.exec(refusal ?? '')?.[1];
    if (status === '401') {
      const given = this.#options.token === undefined ? 'no token was given' : 'the token is wrong';
      return new HalError(
        'AUTH_FAILED',
        `${url} refused the connection (HTTP 401): ${given} (the server's --token or $HAL_SERVE_TOKEN)`,
        { details: { httpStatus: 401 } },
      );
    }
    if (status === '403') {
      return new HalError(
        'AUTH_FAILED',
        `${url} refused the connection (HTTP 403): the server, having no token, trusts only this machine's programs and pages, and this client's Origin or Host is not one of them (its log says which; --allow-origin trusts a page's origin)`,
        { details: { httpStatus: 403 } },
      );
    }
    if (status !== undefined) {
      return new HalError(
        'NOT_CONNECTED',
        `${url} answered HTTP ${status}, not a WebSocket upgrade: is it a HAL server?`,
        { details: { httpStatus: Number(status) } },
      );
    }
    const why = refusal === undefined ? '' : `: ${refusal}`;
    return new HalError(
      'NOT_CONNECTED',
      `cannot connect to ${url} (closed ${event.code}${event.reason ? `: ${event.reason}` : ''}${why})`,
      { details: { closeCode: event.code } },
    );
  }

  #onMessage(data: unknown): void {
    if (typeof data !== 'string') {
      this.#log('warn', 'ignored a binary message');
      return;
    }
    let message: ReturnType<typeof decodeMessage>;
    try {
      message = decodeMessage(data);
    } catch (e) {
      this.#log('warn', 'ignored a malformed message', { error: String(e) });
      return;
    }
    switch (message.schema) {
      case MESSAGE_SCHEMAS.hello:
        this.hello = message.envelope.payload;
        this.role = message.envelope.payload.role;
        return;
      case MESSAGE_SCHEMAS.reply: {
        const reply = message.envelope.payload;
        this.safety = reply.safety;
        if (reply.id === null) {
          if (!reply.ok) this.#log('warn', 'server refused a message', { error: reply.error });
          return;
        }
        if (reply.ok) this.#settle(reply.id, undefined, reply.value);
        else {
          const { code, message: text, details } = reply.error;
          this.#settle(
            reply.id,
            new HalError(code as HalErrorCode, text, details === undefined ? {} : { details }),
          );
        }
        return;
      }
      case MESSAGE_SCHEMAS.state: {
        const state = message.envelope.payload;
        this.safety = state.safety;
        this.pose = state.pose;
        this.moving = state.moving;
        this.role = state.role;
        return;
      }
      case MESSAGE_SCHEMAS.control: {
        const { role, reason } = message.envelope.payload;
        this.role = role;
        for (const listener of this.roleListeners) listener(role, reason);
        return;
      }
      default:
        this.#log('warn', `ignored a "${message.schema}" message`);
    }
  }

  #settle(id: string, error: HalError | undefined, value?: unknown): void {
    const pending = this.#pending.get(id);
    if (pending === undefined) return;
    this.#pending.delete(id);
    clearTimeout(pending.timer);
    if (error === undefined) pending.resolve(value);
    else pending.reject(error);
  }

  #onClose(socket: WebSocketLike, code: number, reason: string): void {
    if (this.#socket !== socket) return;
    this.#log('warn', `connection closed (${code}${reason ? `: ${reason}` : ''})`);
    this.#teardown(`the connection closed (${code})`);
    if (this.#wanted && this.#options.reconnect) this.#scheduleReconnect();
  }

  #teardown(why: string): void {
    clearInterval(this.#heartbeat);
    const socket = this.#socket;
    this.#socket = undefined;
    this.hello = undefined;
    this.role = 'watcher';
    if (socket !== undefined) {
      socket.onclose = null;
      socket.onmessage = null;
      socket.close(1000, 'client closing');
    }
    for (const id of [...this.#pending.keys()]) {
      this.#settle(id, new HalError('NOT_CONNECTED', `${why}; the call's outcome is unknown`));
    }
  }

  #scheduleReconnect(): void {
    clearTimeout(this.#reconnectTimer);
    this.#reconnectTimer = setTimeout(() => {
      if (!this.#wanted) return;
      this.#connect().catch((e: unknown) => {
        this.#log('debug', 'reconnect failed', { error: String(e) });
        this.#delay = Math.min(5000, this.#delay * 2);
        if (this.#wanted) this.#scheduleReconnect();
      });
    }, this.#delay);
  }
}
