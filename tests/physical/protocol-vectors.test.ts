import { createSocket } from 'node:dgram';
import { MockRobot } from '@hal/physical/testing';
import { afterAll, describe, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { PROTOCOL_CASES, runCase } from './protocol-vectors.js';
import type { VectorDevice } from './protocol-vectors.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 20;
const heartbeat = new TextEncoder().encode('{"cmd":"heartbeat"}');

describe('the golden protocol exchanges, decoded by @hal/physical', () => {
  describe('against the emulator over UDP', () => {
    for (const testCase of PROTOCOL_CASES) {
      it(testCase.name, async () => {
        const emulator = await startEmulator({ timeScale: TIME_SCALE, pty: false });
        const socket = createSocket('udp4');
        await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
        const replies: Buffer[] = [];
        const waiters: Array<() => void> = [];
        socket.on('message', (message) => {
          replies.push(message);
          waiters.shift()?.();
        });
        const exchange = async (bytes: Uint8Array): Promise<Uint8Array> => {
          const got = new Promise<void>((resolve, reject) => {
            const timer = setTimeout(() => reject(new Error('no reply from the emulator')), 5000);
            waiters.push(() => {
              clearTimeout(timer);
              resolve();
            });
          });
          socket.send(bytes, emulator.udpPort, '127.0.0.1');
          await got;
          return new Uint8Array(replies.shift()!);
        };
        const device: VectorDevice = {
          exchange,
          advance: async (ms) => {
            // let the robot's clock run, with the host sending (seed-style) heartbeats
            const until = performance.now() + ms / TIME_SCALE;
            while (performance.now() < until) {
              await exchange(heartbeat);
              await new Promise((resolve) => setTimeout(resolve, 5));
            }
          },
        };
        try {
          await runCase(device, testCase, { exactMessages: true });
        } finally {
          socket.close();
          await emulator.stop();
        }
      });
    }
  });

  describe('against the in-process mock robot (error wording aside)', () => {
    for (const testCase of PROTOCOL_CASES) {
      it(testCase.name, async () => {
        let now = 0;
        const robot = new MockRobot({ now: () => now });
        const device: VectorDevice = {
          exchange: async (bytes) => robot.handle(bytes),
          advance: async (ms) => {
            for (let t = 0; t < ms; t += 100) {
              now += Math.min(100, ms - t);
              robot.handle(heartbeat);
            }
          },
        };
        await runCase(device, testCase, { exactMessages: false });
      });
    }
  });
});
