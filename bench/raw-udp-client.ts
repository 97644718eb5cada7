// The alternative the UDP benchmarks and tools measure PhysicalHAL against: a node:dgram socket
// connected to the emulator, one request at a time, each reply parsed (and, with a key, signed
// requests and every reply's MAC checked in constant time, or the key protects nothing), its seq
// checked by the caller, as any client must.
import { createHmac, timingSafeEqual } from 'node:crypto';
import { createSocket } from 'node:dgram';

/** What the raw client reads of a reply. */
export interface RawReply {
  seq: number;
  sid?: number;
}

export interface RawUdpClient {
  /** The session id the emulator gave the client's `hello`. */
  readonly sid: number | undefined;
  /** Sends one request (JSON text) and resolves with its parsed reply. */
  ask(json: string): Promise<RawReply>;
  close(): void;
}

/** The benchmarks' command: `set_led` with red `i % 256`. */
export const setLedJson = (seq: number, sid: number | undefined, i: number): string =>
  `{"cmd":"set_led","seq":${seq},"sid":${sid},"r":${i % 256},"g":0,"b":0,"pattern":"solid"}`;

/** Connects to the emulator on 127.0.0.1:`port` and says `hello` (seq 1). */
export async function openRawUdpClient(port: number, key?: string): Promise<RawUdpClient> {
  const socket = createSocket('udp4');
  await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
  socket.connect(port, '127.0.0.1');
  await new Promise<void>((resolve) => socket.once('connect', resolve));
  const secret = key === undefined ? undefined : Buffer.from(key, 'hex');
  const sign = (json: string) =>
    secret === undefined
      ? json
      : `${json}#${createHmac('sha256', secret).update(json).digest('hex').slice(0, 32)}`;
  const authentic = (json: string, mac: string) =>
    secret === undefined ||
    (mac.length === 32 &&
      timingSafeEqual(
        Buffer.from(mac, 'hex'),
        createHmac('sha256', secret).update(json).digest().subarray(0, 16),
      ));
  let waiting: ((reply: Buffer) => void) | undefined;
  socket.on('message', (message) => waiting?.(message));
  const ask = (json: string) =>
    new Promise<RawReply>((resolve, reject) => {
      waiting = (reply) => {
        const text = reply.toString();
        const end = secret === undefined ? text.length : text.lastIndexOf('#');
        const body = text.slice(0, end);
        if (!authentic(body, text.slice(end + 1)))
          reject(new Error('raw: reply MAC does not match'));
        else resolve(JSON.parse(body) as RawReply);
      };
      socket.send(sign(json));
    });
  const nonce = secret === undefined ? '' : `,"nonce":"${Date.now().toString(16)}"`;
  const hello = await ask(`{"cmd":"hello","seq":1${nonce}}`);
  return { sid: hello.sid, ask, close: () => socket.close() };
}
