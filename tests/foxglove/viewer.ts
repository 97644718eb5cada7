// A Foxglove viewer for the tests: the real `@foxglove/ws-protocol` client over `ws`, which
// subscribes to topics by name, collects what it receives, publishes and calls services.
import { createRequire } from 'node:module';
import type * as WsProtocolModule from '@foxglove/ws-protocol';
import type {
  Channel,
  IWebSocket,
  Service,
  ServerInfo,
  StatusMessage,
} from '@foxglove/ws-protocol';
import { WebSocket } from 'ws';

// the package's CommonJS main hides its named exports from Node's ES module loader
const { FoxgloveClient } = createRequire(import.meta.url)(
  '@foxglove/ws-protocol',
) as typeof WsProtocolModule;
type FoxgloveClient = InstanceType<typeof FoxgloveClient>;

export interface Received {
  topic: string;
  /** The message's log time, ns. */
  at: bigint;
  value: Record<string, unknown>;
  /** When the viewer had it, ms since the epoch (to the microsecond). */
  receivedAtMs: number;
}

export interface Viewer {
  client: FoxgloveClient;
  /** The viewer's own socket (a test may stall it). */
  socket: WebSocket;
  info: ServerInfo;
  channels: Channel[];
  services: Service[];
  received: Received[];
  statuses: StatusMessage[];
  /** The messages received on `topic` so far. */
  on(topic: string): Received[];
  /** Subscribes to `topics`; resolves once the server has taken the subscriptions. */
  subscribe(...topics: string[]): Promise<void>;
  /** Resolves once `predicate` holds of what was received (checked on every message). */
  until(predicate: () => boolean): Promise<void>;
  /** Calls a service by name with a JSON request; resolves with its JSON response. */
  call(name: string, request?: Record<string, unknown>): Promise<Record<string, unknown>>;
  /** Advertises a JSON channel on `topic` and returns a function that publishes on it. */
  publisher(topic: string, schemaName: string): (message: unknown) => void;
  close(): void;
}

const decoder = new TextDecoder();
const encoder = new TextEncoder();

/** Connects to `url` as a viewer; resolves once the server has said what it offers. */
export async function connectViewer(
  url: string,
  headers: Record<string, string> = {},
): Promise<Viewer> {
  const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL], { headers });
  // ws's socket is the browser WebSocket the client expects, its send overloaded for Node
  const client = new FoxgloveClient({ ws: ws as unknown as IWebSocket });
  const channels: Channel[] = [];
  const services: Service[] = [];
  const received: Received[] = [];
  const statuses: StatusMessage[] = [];
  const bySubscription = new Map<number, string>();
  const waiters = new Set<() => void>();
  const wake = () => {
    for (const w of [...waiters]) w();
  };
  client.on('advertise', (c) => {
    channels.push(...c);
    wake();
  });
  client.on('advertiseServices', (s) => {
    services.push(...s);
    wake();
  });
  client.on('status', (s) => {
    statuses.push(s);
    wake();
  });
  client.on('message', (event) => {
    const topic = bySubscription.get(event.subscriptionId) ?? '?';
    const receivedAtMs = performance.timeOrigin + performance.now();
    const value = JSON.parse(decoder.decode(event.data)) as Record<string, unknown>;
    received.push({ topic, at: event.timestamp, value, receivedAtMs });
    wake();
  });
  const info = await new Promise<ServerInfo>((resolve, reject) => {
    client.on('serverInfo', resolve);
    client.on('error', reject);
    ws.once('unexpected-response', (_req, res) => reject(new Error(`HTTP ${res.statusCode}`)));
  });
  // checked on every message, and every 20 ms for what the server counts (its stats)
  const until = (predicate: () => boolean) =>
    new Promise<void>((resolve) => {
      const check = () => {
        if (!predicate()) return;
        waiters.delete(check);
        clearInterval(timer);
        resolve();
      };
      const timer = setInterval(check, 20);
      waiters.add(check);
      check();
    });
  await until(() => channels.length > 0 && services.length > 0);
  let nextCall = 1;
  const responses = new Map<number, (value: Record<string, unknown>) => void>();
  client.on('serviceCallResponse', (r) => {
    responses.get(r.callId)?.(JSON.parse(decoder.decode(r.data)) as Record<string, unknown>);
  });
  return {
    client,
    socket: ws,
    info,
    channels,
    services,
    received,
    statuses,
    on: (topic) => received.filter((r) => r.topic === topic),
    async subscribe(...topics) {
      for (const topic of topics) {
        const channel = channels.find((c) => c.topic === topic);
        if (channel === undefined) throw new Error(`no channel ${topic}`);
        bySubscription.set(client.subscribe(channel.id), topic);
      }
      // the server answers a repeated subscription with a status, after taking the ones before
      const pose = channels.find((c) => c.topic.endsWith('/hal/pose/raw'));
      if (pose === undefined) return;
      const seen = statuses.length;
      const probe = client.subscribe(pose.id);
      client.subscribe(pose.id);
      await until(() => statuses.length > seen);
      statuses.splice(seen);
      client.unsubscribe(probe);
    },
    until,
    call(name, request = {}) {
      const service = services.find((s) => s.name === name);
      if (service === undefined) throw new Error(`no service ${name}`);
      const callId = nextCall++;
      return new Promise((resolve) => {
        responses.set(callId, resolve);
        client.sendServiceCallRequest({
          serviceId: service.id,
          callId,
          encoding: 'json',
          data: encoder.encode(JSON.stringify(request)),
        });
      });
    },
    publisher(topic, schemaName) {
      const id = client.advertise({ topic, encoding: 'json', schemaName });
      return (message) => client.sendMessage(id, encoder.encode(JSON.stringify(message)));
    },
    close: () => client.close(),
  };
}
