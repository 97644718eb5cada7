import { createSocket } from 'node:dgram';
import type { Socket } from 'node:dgram';
import { afterEach, describe, expect, it } from 'vitest';
import { silentLogger } from '@hal/types';
import { MessageCodec } from '../protocol/codec.js';
import type { Transport } from './transport.js';
import { udpTransport } from './udp.js';

const codec = new MessageCodec();
const context = { decode: (b: Uint8Array) => codec.decode(b), logger: silentLogger };
const encode = (value: unknown) => Buffer.from(JSON.stringify(value));

/** A UDP peer on 127.0.0.1 whose answer to each request the test decides. */
async function peer(
  answer: (request: Record<string, unknown>, reply: (bytes: Buffer) => void, count: number) => void,
): Promise<{ socket: Socket; port: number; received: Record<string, unknown>[] }> {
  const socket = createSocket('udp4');
  const received: Record<string, unknown>[] = [];
  socket.on('message', (message, remote) => {
    const request = JSON.parse(message.toString()) as Record<string, unknown>;
    received.push(request);
    answer(request, (bytes) => socket.send(bytes, remote.port, remote.address), received.length);
  });
  await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
  return { socket, port: socket.address().port, received };
}

describe('udpTransport', () => {
  const cleanups: Array<() => Promise<void> | void> = [];
  afterEach(async () => {
    for (const cleanup of cleanups.splice(0)) await cleanup();
  });

  async function connect(port: number, timeoutMs = 100): Promise<Transport> {
    const transport = await udpTransport({ host: '127.0.0.1', port, timeoutMs }).connect(context);
    cleanups.push(() => transport.close());
    return transport;
  }

  it('matches the reply by its echoed seq, dropping garbage, stray and stale datagrams', async () => {
    const p = await peer((request, reply) => {
      reply(Buffer.from('not json'));
      reply(encode({ seq: 999, ok: true }));
      reply(encode({ ok: true }));
      reply(encode({ seq: request['seq'], ok: true, cmd: 'heartbeat', uptime_ms: 1 }));
    });
    cleanups.push(() => void p.socket.close());
    const transport = await connect(p.port);
    const reply = await transport.request(7, encode({ cmd: 'heartbeat', seq: 7, sid: 1 }));
    expect(reply.seq).toBe(7);
    await expect.poll(() => transport.stats().dropped, { timeout: 2000 }).toBe(3);
    expect(transport.stats()).toMatchObject({ sent: 1, received: 1, retries: 0, timeouts: 0 });
  });

  it('resends the same bytes after a timeout and counts the retries', async () => {
    const p = await peer((request, reply, count) => {
      if (count >= 3) reply(encode({ seq: request['seq'], ok: true }));
    });
    cleanups.push(() => void p.socket.close());
    const transport = await connect(p.port, 50);
    const bytes = encode({ cmd: 'move_cm', seq: 4, sid: 1, left_cm: 1, right_cm: 1 });
    await transport.request(4, bytes);
    expect(p.received).toHaveLength(3);
    expect(new Set(p.received.map((r) => JSON.stringify(r))).size).toBe(1);
    expect(transport.stats()).toMatchObject({ sent: 3, received: 1, retries: 2, timeouts: 0 });
    expect(transport.stats().rttP50Ms).toBeGreaterThanOrEqual(0);
  });

  it('rejects with TIMEOUT after three unanswered attempts', async () => {
    const p = await peer(() => undefined);
    cleanups.push(() => void p.socket.close());
    const transport = await connect(p.port, 30);
    await expect(transport.request(1, encode({ seq: 1 }))).rejects.toMatchObject({
      code: 'TIMEOUT',
    });
    expect(p.received).toHaveLength(3);
    expect(transport.stats().timeouts).toBe(1);
  });

  it('rejects pending requests with NOT_CONNECTED when closed', async () => {
    const p = await peer(() => undefined);
    cleanups.push(() => void p.socket.close());
    const transport = await connect(p.port, 5000);
    const pending = transport.request(1, encode({ seq: 1 }));
    await transport.close();
    await expect(pending).rejects.toMatchObject({ code: 'NOT_CONNECTED' });
  });

  describe('a forged reply', () => {
    /** A socket that sends forged datagrams, bound to `address:port`. */
    async function spoofer(address: string, port: number): Promise<Socket> {
      const socket = createSocket('udp4');
      cleanups.push(() => void socket.close());
      await new Promise<void>((resolve) => socket.bind(port, address, resolve));
      return socket;
    }

    /**
     * A robot that answers each request after 100 ms, and a spoofer that answers it at once, from
     * `from` (address and port): the spoofer's reply always arrives first.
     */
    async function race(from: (robotPort: number) => { address: string; port: number }) {
      const robot = await peer((request, reply) => {
        setTimeout(() => reply(encode({ seq: request['seq'], ok: true, from: 'robot' })), 100);
      });
      cleanups.push(() => void robot.socket.close());
      const source = from(robot.port);
      const forger = await spoofer(source.address, source.port);
      let forged = 0;
      const forge = (request: Record<string, unknown>, to: number) => {
        forged += 1;
        const reply = { seq: request['seq'], ok: true, from: 'spoofer', running: false };
        forger.send(encode(reply), to, '127.0.0.1');
      };
      const transport = await connect(robot.port, 2000);
      const localPort = (transport as Transport & { localPort: number }).localPort;
      const request = { cmd: 'get_status', seq: 5, sid: 1 };
      const replying = transport.request(5, encode(request));
      forge(request, localPort);
      forge(request, localPort);
      const reply = await replying;
      return { reply, forged, stats: transport.stats() };
    }

    it("from another address, even from the robot's port number, never reaches the HAL", async () => {
      const { reply, forged, stats } = await race((robotPort) => ({
        address: '127.0.0.2',
        port: robotPort,
      }));
      expect(forged).toBe(2);
      expect(reply['from']).toBe('robot');
      expect(stats).toMatchObject({ received: 1, dropped: 0 });
    });

    it("from the robot's address but another port never reaches the HAL", async () => {
      const { reply, forged, stats } = await race(() => ({ address: '127.0.0.1', port: 0 }));
      expect(forged).toBe(2);
      expect(reply['from']).toBe('robot');
      expect(stats).toMatchObject({ received: 1, dropped: 0 });
    });
  });

  it('waits each attempt out while the robot port is unreachable, as for lost datagrams', async () => {
    const gone = createSocket('udp4');
    await new Promise<void>((resolve) => gone.bind(0, '127.0.0.1', resolve));
    const port = gone.address().port;
    await new Promise<void>((resolve) => gone.close(resolve));
    const logged: string[] = [];
    const transport = await udpTransport({ host: '127.0.0.1', port, timeoutMs: 60 }).connect({
      ...context,
      logger: { log: (level, _namespace, message) => logged.push(`${level}: ${message}`) },
    });
    cleanups.push(() => transport.close());
    const started = performance.now();
    await expect(transport.request(1, encode({ seq: 1 }))).rejects.toMatchObject({
      code: 'TIMEOUT',
    });
    // three attempts, each waited out: the ICMP errors did not cut them short
    expect(performance.now() - started).toBeGreaterThanOrEqual(3 * 60 - 5);
    expect(transport.stats()).toMatchObject({ sent: 3, timeouts: 1 });
    expect(logged.filter((line) => !line.startsWith('debug'))).toEqual([]);
  });

  it('fails to connect to a name that does not resolve with the lookup error, at once', async () => {
    const transport = udpTransport({ host: 'nosuchhost.invalid', port: 4210 });
    await expect(transport.connect(context)).rejects.toMatchObject({
      code: 'NOT_CONNECTED',
      message: expect.stringMatching(
        /^cannot reach the robot at nosuchhost\.invalid:4210: getaddrinfo (ENOTFOUND|EAI_AGAIN) nosuchhost\.invalid$/,
      ),
      details: { host: 'nosuchhost.invalid', port: 4210, errno: expect.stringMatching(/^E/) },
    });
  });

  it('refuses a bad port with a message that quotes the argument', () => {
    expect(() => udpTransport({ host: '127.0.0.1', port: 70000 })).toThrow('"port"');
  });
});
