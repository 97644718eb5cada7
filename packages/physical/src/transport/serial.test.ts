import { describe, expect, it } from 'vitest';
import { silentLogger } from '@hal/types';
import { MockRobot } from '../mock/mock-robot.js';
import { MessageCodec } from '../protocol/codec.js';
import { PhysicalHAL } from '../hal/physical-hal.js';
import { encodeFrame } from '../serial/frame.js';
import { FrameDecoder } from '../serial/frame-decoder.js';
import type { FrameType } from '../serial/frame.js';
import type { SerialPortLike } from './serial.js';
import { serialTransport } from './serial.js';

/**
 * A serial port whose other end is a mock robot behind the frame layer: it ACKs every DATA frame,
 * delivers a repeated link seq once, and answers in DATA frames (corrupting every `corruptEvery`th
 * one, if asked).
 */
class FramedMockPort implements SerialPortLike {
  isOpen = true;
  readonly #robot: MockRobot;
  readonly #decoder = new FrameDecoder({
    onFrame: (type, seq, payload) => this.#receive(type, seq, payload),
  });
  readonly #listeners = {
    data: [] as Array<(c: Uint8Array) => void>,
    close: [] as Array<() => void>,
  };
  readonly #corruptEvery: number;
  #txSeq = 500;
  #sent = 0;
  #lastDelivered: number | undefined;

  constructor(robot: MockRobot, corruptEvery = 0) {
    this.#robot = robot;
    this.#corruptEvery = corruptEvery;
  }

  write(data: Uint8Array, callback?: (error?: Error | null) => void): boolean {
    const bytes = data.slice();
    setTimeout(() => this.#decoder.push(bytes), 0);
    callback?.(null);
    return true;
  }

  /** A frame from the host: ACK it, and answer a DATA frame not seen before. */
  #receive(type: FrameType, seq: number, payload: Uint8Array): void {
    if (type !== 'data') return;
    this.#emit(encodeFrame({ type: 'ack', seq, payload: new Uint8Array(0) }));
    if (seq === this.#lastDelivered) return;
    this.#lastDelivered = seq;
    const reply = this.#robot.receive(payload);
    if (reply === undefined) return;
    const frame = encodeFrame({ type: 'data', seq: this.#txSeq++ & 0xffff, payload: reply });
    this.#sent += 1;
    if (this.#corruptEvery > 0 && this.#sent % this.#corruptEvery === 0) frame[12]! ^= 0x04;
    this.#emit(frame);
  }

  on(event: 'data' | 'error' | 'close', listener: (value: never) => void): this {
    if (event === 'data') this.#listeners.data.push(listener as (c: Uint8Array) => void);
    if (event === 'close') this.#listeners.close.push(listener as () => void);
    return this;
  }

  close(callback?: (error?: Error | null) => void): void {
    this.unplug();
    callback?.(null);
  }

  /** The cable is pulled. */
  unplug(): void {
    if (!this.isOpen) return;
    this.isOpen = false;
    for (const listener of this.#listeners.close) listener();
  }

  #emit(bytes: Uint8Array): void {
    if (!this.isOpen) return;
    for (const listener of this.#listeners.data) listener(bytes);
  }
}

function halOver(robot: MockRobot, ports: FramedMockPort[], corruptEvery = 0): PhysicalHAL {
  const open = async () => {
    const port = new FramedMockPort(robot, corruptEvery);
    ports.push(port);
    return port;
  };
  return new PhysicalHAL(
    { mode: 'physical', deviceId: 'cube-serial' },
    { transport: serialTransport({ path: 'mock', open, timeoutMs: 50 }), timeScale: 50 },
  );
}

describe('serialTransport', () => {
  it('carries PhysicalHAL to the robot in acknowledged frames', async () => {
    const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000 });
    const hal = halOver(robot, []);
    await hal.initialize();
    expect((await hal.locomotion.moveForward(5)).success).toBe(true);
    expect(robot.position).toEqual({ left: 1086, right: 1086 });
    const link = hal.linkStats()!;
    expect(link.framesSent).toBeGreaterThan(2);
    expect(link.acksReceived).toBe(link.framesSent);
    expect(link.acksSent).toBe(link.framesReceived);
    await hal.cleanup();
  });

  it('drops corrupted reply frames by their CRC and recovers each reply exactly once', async () => {
    const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000 });
    const hal = halOver(robot, [], 3);
    await hal.initialize();
    for (let i = 0; i < 5; i++) expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    expect(robot.motionsStarted).toBe(5);
    expect(hal.linkStats()!.checksumErrors).toBeGreaterThan(0);
    expect(hal.transportStats()!.retries).toBeGreaterThan(0);
    await hal.cleanup();
  });

  it('reopens the port after it goes away', async () => {
    const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000 });
    const ports: FramedMockPort[] = [];
    const hal = halOver(robot, ports);
    await hal.initialize();
    ports[0]!.unplug();
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    expect(ports).toHaveLength(2);
    await hal.cleanup();
  });

  it("fails to open with NOT_CONNECTED that keeps the system's reason, not a timeout", async () => {
    const enoent = Object.assign(new Error('No such file or directory, cannot open /dev/ttyNOPE'), {
      code: 'ENOENT',
    });
    const transport = serialTransport({
      path: '/dev/ttyNOPE',
      open: () => Promise.reject(enoent),
    });
    const codec = new MessageCodec();
    const opened = transport.connect({ decode: (b) => codec.decode(b), logger: silentLogger });
    await expect(opened).rejects.toMatchObject({
      code: 'NOT_CONNECTED',
      message:
        'cannot open serial port /dev/ttyNOPE: No such file or directory, cannot open /dev/ttyNOPE',
      details: { path: '/dev/ttyNOPE', errno: 'ENOENT' },
      cause: enoent,
    });
  });

  it('refuses a bad baud rate with a message that quotes the argument', () => {
    expect(() => serialTransport({ path: '/dev/ttyUSB0', baudRate: -1 })).toThrow('"baudRate"');
  });
});
