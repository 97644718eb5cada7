// Someone else on the network forges the robot's replies while PhysicalHAL drives the emulated
// robot over UDP: a `get_status` that says the move is done, sent the moment the HAL asks, from
// another address (even from the robot's port number) and from the robot's address but another
// port. The HAL's socket is connected to the robot, so none of it reaches the HAL: the move
// completes when, and only when, the robot has really made its steps.
import { createSocket } from 'node:dgram';
import type { Socket } from 'node:dgram';
import { PhysicalHAL, udpTransport } from '@hal/physical';
import type { TransportFactory, UdpTransport } from '@hal/physical';
import type { WireReply } from '@hal/physical/protocol';
import type { Logger, LogLevel } from '@hal/types';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import type { Emulator } from './emulator.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 5;
const STEPS_10_CM = 2172;

type Json = Record<string, unknown>;

/** Wraps the UDP transport to see what the HAL sends and receives (what a sniffer would see). */
function observed(
  inner: TransportFactory<'udp'>,
  onRequest: (request: Json, localPort: number) => void,
  onReply: (reply: WireReply) => void,
): TransportFactory<'udp'> {
  return {
    type: 'udp',
    connect: async (context) => {
      const transport = (await inner.connect(context)) as UdpTransport;
      return {
        ...transport,
        request: async (seq, bytes, options) => {
          onRequest(JSON.parse(new TextDecoder().decode(bytes)) as Json, transport.localPort);
          const reply = await transport.request(seq, bytes, options);
          onReply(reply);
          return reply;
        },
      };
    },
  };
}

async function bound(address: string, port: number): Promise<Socket> {
  const socket = createSocket('udp4');
  await new Promise<void>((resolve) => socket.bind(port, address, resolve));
  return socket;
}

/** The robot's own status, asked from a socket of our own (the keyless emulator accepts it). */
async function robotStatus(port: number): Promise<Json> {
  const socket = await bound('127.0.0.1', 0);
  try {
    return await new Promise<Json>((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error('the robot did not answer')), 2000);
      socket.once('message', (message) => {
        clearTimeout(timer);
        resolve(JSON.parse(message.toString()) as Json);
      });
      socket.send('{"cmd":"get_status"}', port, '127.0.0.1');
    });
  } finally {
    socket.close();
  }
}

describe('PhysicalHAL over UDP with a spoofer on the network', () => {
  let emulator: Emulator | undefined;
  let hal: PhysicalHAL | undefined;
  const sockets: Socket[] = [];

  afterEach(async () => {
    await hal?.cleanup();
    await emulator?.stop();
    for (const socket of sockets.splice(0)) socket.close();
  });

  it('ignores a forged "move done" status from another address or port while a real move runs', async () => {
    emulator = await startEmulator({ timeScale: TIME_SCALE, pty: false });
    // the robot's port number, on another loopback address; and the robot's address, another port
    const otherAddress = await bound('127.0.0.2', emulator.udpPort);
    const otherPort = await bound('127.0.0.1', 0);
    sockets.push(otherAddress, otherPort);

    let moveId: number | undefined;
    let lastStatus: Json | undefined;
    let forged = 0;
    const send = (reply: Json, localPort: number) => {
      const bytes = Buffer.from(JSON.stringify(reply));
      for (const socket of [otherAddress, otherPort]) {
        socket.send(bytes, localPort, '127.0.0.1');
        forged += 1;
      }
    };
    // What the spoofer answers, at once, to what it sniffed: the move "takes 1 ms", and every
    // status says it is done.
    const forge = (request: Json, localPort: number) => {
      if (lastStatus === undefined) return;
      const envelope = { seq: request['seq'], sid: request['sid'], ok: true, cmd: request['cmd'] };
      const nextMove = (lastStatus['move_id'] as number) + 1;
      if (request['cmd'] === 'move_cm') {
        send(
          {
            ...envelope,
            move_id: nextMove,
            left_steps: STEPS_10_CM,
            right_steps: STEPS_10_CM,
            speed: 1024,
            speed_clamped: false,
            duration_ms: 1,
            duration_us: 1000,
          },
          localPort,
        );
      } else if (request['cmd'] === 'get_status') {
        send(
          {
            ...lastStatus,
            ...envelope,
            running: false,
            move_id: moveId ?? nextMove,
            move_outcome: 'done',
            move_left_steps: STEPS_10_CM,
            move_right_steps: STEPS_10_CM,
            left_steps: STEPS_10_CM,
            right_steps: STEPS_10_CM,
            left_sps: 0,
            right_sps: 0,
          },
          localPort,
        );
      }
    };
    const transport = observed(
      udpTransport({ host: '127.0.0.1', port: emulator.udpPort }),
      forge,
      (reply) => {
        if (reply.cmd === 'get_status' && reply.ok) lastStatus = { ...reply };
        if (reply.cmd === 'move_cm' && reply.ok) moveId = reply['move_id'] as number;
      },
    );
    hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-spoofed' },
      { transport, timeScale: TIME_SCALE },
    );
    await hal.initialize();

    const result = await hal.locomotion.moveForward(10);
    expect(result.success).toBe(true);
    expect(forged).toBeGreaterThanOrEqual(4);
    // the HAL said "done" only once the robot was really done: ask the robot itself
    const status = await robotStatus(emulator.udpPort);
    expect(status).toMatchObject({
      running: false,
      move_id: moveId,
      move_outcome: 'done',
      left_steps: STEPS_10_CM,
      right_steps: STEPS_10_CM,
    });
    expect(moveId).toBe(1);
  });

  it('reports a robot without authentication in its identity and warns through the logger', async () => {
    emulator = await startEmulator({ timeScale: TIME_SCALE, pty: false });
    const warnings: string[] = [];
    const logger: Logger = {
      log: (level: LogLevel, _namespace: string, message: string) => {
        if (level === 'warn') warnings.push(message);
      },
    };
    hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-open',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE, logger },
    );
    await hal.initialize();
    expect(hal.identity).toMatchObject({ auth: false, authScheme: 'none', protocolVersion: '1.1' });
    expect(warnings.some((w) => w.includes('without authentication'))).toBe(true);
  });
});
