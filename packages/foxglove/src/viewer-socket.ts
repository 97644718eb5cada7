// One viewer's socket as the protocol server sees it, with a bounded send queue: a message on a
// topic goes out only while fewer than `maxQueuedBytes` wait in the socket's buffer; beyond that
// it is dropped and counted for its topic. Sending never waits, so a slow viewer (a throttled
// link, a busy laptop) never slows the robot or the other viewers; it just sees fewer messages.
import type { IWebSocket } from '@foxglove/ws-protocol';
import type { WebSocket } from 'ws';

/** The protocol's opcode of a message on a subscribed topic (server to client). */
const MESSAGE_DATA = 1;

/** Counts of one viewer, by topic. */
export interface ViewerCounts {
  sent: Map<string, number>;
  dropped: Map<string, number>;
}

/** Handlers the socket calls besides the protocol server's own. */
export interface ViewerSocketHooks {
  /** The first message dropped on a topic for this viewer (to say so once). */
  firstDrop(topic: string): void;
}

function increment(map: Map<string, number>, key: string): void {
  map.set(key, (map.get(key) ?? 0) + 1);
}

export class ViewerSocket implements IWebSocket {
  readonly counts: ViewerCounts = { sent: new Map(), dropped: new Map() };
  readonly #socket: WebSocket;
  readonly #maxQueuedBytes: number;
  readonly #topicOfChannel: (channelId: number) => string | undefined;
  readonly #hooks: ViewerSocketHooks;
  /** The viewer's subscription ids and the topics they name. */
  readonly #subscriptions = new Map<number, string>();
  #onmessage: ((event: { data: unknown }) => void) | null | undefined;

  constructor(
    socket: WebSocket,
    maxQueuedBytes: number,
    topicOfChannel: (channelId: number) => string | undefined,
    hooks: ViewerSocketHooks,
  ) {
    this.#socket = socket;
    this.#maxQueuedBytes = maxQueuedBytes;
    this.#topicOfChannel = topicOfChannel;
    this.#hooks = hooks;
    socket.on('message', (data, isBinary) => {
      const text = isBinary ? undefined : Buffer.from(data as Buffer).toString('utf8');
      if (text !== undefined) this.#peek(text);
      const event = {
        data:
          text ??
          (Buffer.isBuffer(data)
            ? data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength)
            : data),
      };
      this.#onmessage?.(event);
    });
  }

  get binaryType(): string {
    return this.#socket.binaryType;
  }
  set binaryType(_value: string) {
    // messages are handed on as text or an ArrayBuffer whatever is asked
  }
  get protocol(): string {
    return this.#socket.protocol;
  }
  onerror: ((event: unknown) => void) | null | undefined;
  onopen: ((event: unknown) => void) | null | undefined;
  get onclose(): ((event: unknown) => void) | null | undefined {
    return this.#socket.onclose as ((event: unknown) => void) | null;
  }
  set onclose(handler: ((event: unknown) => void) | null | undefined) {
    this.#socket.onclose = handler ?? null;
  }
  get onmessage(): ((event: { data: unknown }) => void) | null | undefined {
    return this.#onmessage;
  }
  set onmessage(handler: ((event: { data: unknown }) => void) | null | undefined) {
    this.#onmessage = handler;
  }

  close(): void {
    this.#socket.close();
  }

  /** One argument only: the protocol server then hands each message over in one piece. */
  send(data: string | ArrayBuffer | ArrayBufferView): void {
    if (this.#socket.readyState !== this.#socket.OPEN) return;
    if (typeof data !== 'string') {
      const bytes = ArrayBuffer.isView(data)
        ? new Uint8Array(data.buffer, data.byteOffset, data.byteLength)
        : new Uint8Array(data);
      if (bytes[0] === MESSAGE_DATA && bytes.byteLength >= 5) {
        const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
        const topic = this.#subscriptions.get(view.getUint32(1, true)) ?? '?';
        if (this.#socket.bufferedAmount + bytes.byteLength > this.#maxQueuedBytes) {
          if (!this.counts.dropped.has(topic)) this.#hooks.firstDrop(topic);
          increment(this.counts.dropped, topic);
          return;
        }
        increment(this.counts.sent, topic);
      }
      this.#socket.send(bytes);
      return;
    }
    this.#socket.send(data);
  }

  /** Reads the viewer's subscriptions (to name a dropped message's topic). */
  #peek(text: string): void {
    let message: unknown;
    try {
      message = JSON.parse(text);
    } catch {
      return;
    }
    if (typeof message !== 'object' || message === null) return;
    const m = message as { op?: unknown; subscriptions?: unknown; subscriptionIds?: unknown };
    if (m.op === 'subscribe' && Array.isArray(m.subscriptions)) {
      for (const s of m.subscriptions as Array<{ id?: unknown; channelId?: unknown }>) {
        if (typeof s.id !== 'number' || typeof s.channelId !== 'number') continue;
        // an id already in use is refused by the protocol server; the first one stands
        if (this.#subscriptions.has(s.id)) continue;
        const topic = this.#topicOfChannel(s.channelId);
        if (topic !== undefined) this.#subscriptions.set(s.id, topic);
      }
    }
    if (m.op === 'unsubscribe' && Array.isArray(m.subscriptionIds)) {
      for (const id of m.subscriptionIds)
        if (typeof id === 'number') this.#subscriptions.delete(id);
    }
  }
}
