// The serial link on a real pseudo-terminal, through the `serialport` package, against the emulator.
import { PhysicalHAL } from '@hal/physical';
import { encodeFrame, FrameDecoder, openSerialPort } from '@hal/physical/protocol';
import type { SerialPortLike } from '@hal/physical';
import type { Frame } from '@hal/physical/protocol';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import type { Emulator } from './emulator.js';
import { seededRandom } from './fault-proxy.js';

afterAll(stopAllEmulators);

const encoder = new TextEncoder();
const data = (seq: number, message: object) =>
  encodeFrame({ type: 'data', seq, payload: encoder.encode(JSON.stringify(message)) });

/** A raw frame-level client on the emulator's pseudo-terminal. */
async function rawLink(path: string) {
  const port = await openSerialPort(path, 115200);
  const frames: Frame[] = [];
  const decoder = new FrameDecoder({
    onFrame: (type, seq, payload) => {
      frames.push({ type, seq, payload });
      // acknowledge the device's DATA frames, as a host must
      if (type === 'data')
        port.write(encodeFrame({ type: 'ack', seq, payload: new Uint8Array(0) }));
    },
  });
  // the port's chunks are never written again, so the payloads kept above stay as they came
  port.on('data', (chunk) => decoder.push(chunk));
  const write = (bytes: Uint8Array) =>
    new Promise<void>((resolve, reject) =>
      port.write(bytes, (error) => (error ? reject(error) : resolve())),
    );
  const replies = () =>
    frames
      .filter((f) => f.type === 'data')
      .map((f) => JSON.parse(new TextDecoder().decode(f.payload)) as Record<string, unknown>);
  const acks = (seq: number) => frames.filter((f) => f.type === 'ack' && f.seq === seq).length;
  return {
    write,
    replies,
    acks,
    close: () => new Promise<void>((resolve) => port.close(() => resolve())),
  };
}

describe('the serial link to the emulator', () => {
  let emulator: Emulator;
  afterEach(async () => {
    await emulator?.stop();
  });

  it('acknowledges a duplicate frame again but executes it once', async () => {
    emulator = await startEmulator({ timeScale: 20 });
    const link = await rawLink(emulator.pty);
    try {
      await link.write(data(100, { cmd: 'hello', seq: 1 }));
      await expect.poll(() => link.replies().length, { timeout: 5000 }).toBe(1);
      const sid = link.replies()[0]!['sid'];
      const move = data(101, { cmd: 'move_steps', seq: 2, sid, left: 200, right: 200 });
      await link.write(move);
      await link.write(move);
      await expect.poll(() => link.acks(101), { timeout: 5000 }).toBe(2);
      // a request-level retry in a new frame is answered from the reply memory
      await link.write(data(102, { cmd: 'move_steps', seq: 2, sid, left: 200, right: 200 }));
      await expect.poll(() => link.replies().length, { timeout: 5000 }).toBe(3);
      const [, first, retry] = link.replies();
      expect(retry).toEqual(first);
      expect(emulator.events.filter((e) => e.event === 'move_started')).toHaveLength(1);
    } finally {
      await link.close();
    }
  });

  it('survives random garbage between frames', async () => {
    emulator = await startEmulator({ timeScale: 20 });
    const link = await rawLink(emulator.pty);
    const random = seededRandom(7);
    try {
      await link.write(data(1, { cmd: 'hello', seq: 1 }));
      await expect.poll(() => link.replies().length, { timeout: 5000 }).toBe(1);
      const sid = link.replies()[0]!['sid'];
      const rounds = 20;
      for (let i = 0; i < rounds; i++) {
        const garbage = Uint8Array.from({ length: 1 + Math.floor(random() * 60) }, () =>
          random() < 0.15 ? 0xa5 : Math.floor(random() * 256),
        );
        await link.write(garbage);
        await link.write(data(2 + i, { cmd: 'heartbeat', seq: 2 + i, sid }));
        await expect.poll(() => link.replies().length, { timeout: 5000 }).toBe(2 + i);
      }
      expect(
        link
          .replies()
          .slice(1)
          .every((r) => r['ok'] === true),
      ).toBe(true);
    } finally {
      await link.close();
    }
  });

  it('drives the robot through PhysicalHAL with garbage injected on the line both ways', async () => {
    emulator = await startEmulator({ timeScale: 10 });
    const random = seededRandom(99);
    const noise = () =>
      Uint8Array.from({ length: Math.floor(random() * 24) }, () =>
        random() < 0.2 ? 0xa5 : Math.floor(random() * 256),
      );
    // a port whose every write, and every read, is preceded by line noise
    const open = async (path: string, baudRate: number): Promise<SerialPortLike> => {
      const port = await openSerialPort(path, baudRate);
      return {
        get isOpen() {
          return port.isOpen;
        },
        write: (bytes, callback) => {
          port.write(Buffer.concat([noise(), bytes]), callback);
          return true;
        },
        on: ((event: 'data' | 'error' | 'close', listener: (value: never) => void) => {
          if (event === 'data') {
            port.on('data', (chunk) =>
              (listener as (c: Uint8Array) => void)(Buffer.concat([noise(), chunk])),
            );
          } else if (event === 'error') {
            port.on('error', listener as (e: Error) => void);
          } else {
            port.on('close', listener as () => void);
          }
          return undefined;
        }) as SerialPortLike['on'],
        close: (callback) => port.close(callback),
      };
    };
    const { serialTransport } = await import('@hal/physical');
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-noisy' },
      { transport: serialTransport({ path: emulator.pty, open }), timeScale: 10 },
    );
    try {
      await hal.initialize();
      expect((await hal.locomotion.moveForward(5)).success).toBe(true);
      expect((await hal.locomotion.rotate('right', 45)).success).toBe(true);
      const status = await hal.refreshStatus();
      expect(status.left_steps).toBe(1086 + 853);
      expect(status.right_steps).toBe(1086 - 853);
      expect(hal.linkStats()?.resyncBytes).toBeGreaterThan(0);
    } finally {
      await hal.cleanup();
    }
  });
});
