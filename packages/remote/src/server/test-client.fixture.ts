// A bare WebSocket client that speaks the remote protocol by hand, for server tests: it sees every
// message and can misbehave (send garbage, go silent, vanish).
import { WebSocket } from 'ws';
import { decodeMessage, encodeArgs, encodeMessage } from '../protocol.js';
import type { Message, MessageSchema } from '../protocol.js';

export class TestClient {
  readonly messages: Message[] = [];
  readonly socket: WebSocket;
  #waiters = new Set<() => void>();
  #next = 1;

  private constructor(socket: WebSocket) {
    this.socket = socket;
    socket.on('message', (data) => {
      this.messages.push(decodeMessage(String(data)));
      for (const wake of this.#waiters) wake();
    });
  }

  static async connect(url: string, headers: Record<string, string> = {}): Promise<TestClient> {
    const socket = new WebSocket(url, { headers });
    const client = new TestClient(socket);
    const refused = new Promise<never>((_, reject) => socket.once('error', reject));
    await Promise.race([client.next('hal.remote.hello'), refused]);
    return client;
  }

  /** Waits (up to `timeoutMs`) for the first message that matches. */
  async next<K extends MessageSchema>(
    schema: K,
    match: (m: Extract<Message, { schema: K }>) => boolean = () => true,
    timeoutMs = 5000,
  ): Promise<Extract<Message, { schema: K }>> {
    const find = () =>
      this.messages.find(
        (m): m is Extract<Message, { schema: K }> =>
          m.schema === schema && match(m as Extract<Message, { schema: K }>),
      );
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => {
        this.#waiters.delete(check);
        reject(new Error(`no "${schema}" message within ${timeoutMs} ms`));
      }, timeoutMs);
      const check = () => {
        const found = find();
        if (found === undefined) return;
        clearTimeout(timer);
        this.#waiters.delete(check);
        resolve(found);
      };
      this.#waiters.add(check);
      check();
    });
  }

  /** Sends a call and returns its id. */
  call(call: string, ...args: unknown[]): string {
    const id = `t${this.#next++}`;
    this.raw(
      encodeMessage(
        'hal.remote.call',
        { deviceId: 'test-client' },
        { id, call, args: encodeArgs(args) },
      ),
    );
    return id;
  }

  /** The reply to request `id`. */
  async reply(id: string, timeoutMs = 5000) {
    const message = await this.next(
      'hal.remote.reply',
      (m) => m.envelope.payload.id === id,
      timeoutMs,
    );
    return message.envelope.payload;
  }

  send<K extends MessageSchema>(schema: K, payload: Parameters<typeof encodeMessage<K>>[2]): void {
    this.raw(encodeMessage(schema, { deviceId: 'test-client' }, payload));
  }

  raw(data: string | Buffer): void {
    this.socket.send(data);
  }

  get open(): boolean {
    return this.socket.readyState === WebSocket.OPEN;
  }

  async close(): Promise<void> {
    if (this.socket.readyState === WebSocket.CLOSED) return;
    await new Promise<void>((resolve) => {
      this.socket.once('close', () => resolve());
      this.socket.close();
    });
  }
}
