// A relay between a host and the emulator's serial link that damages the line on purpose,
// reproducibly (seeded): `socat` makes a second pseudo-terminal for the host and hands its bytes
// to this process through its standard streams; the relay cuts the stream into frames, and
// before forwarding each frame it may prepend random garbage, flip one of its bits, or send it
// twice, in each direction at its own rates. The emulator's pseudo-terminal is opened with
// `serialport`, as a host would open it.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { encodeFrame, FrameDecoder, openSerialPort } from '@hal/physical/protocol';
import type { SerialPortLike } from '@hal/physical';
import { seededRandom } from './fault-proxy.js';

/** Per-frame probabilities (0..1) of each kind of damage, one direction. */
export interface LineFaults {
  /** 1..32 random bytes (rich in sync bytes) sent before the frame. */
  garbage: number;
  /** One bit of the frame inverted. */
  bitFlip: number;
  /** The frame sent twice in a row. */
  duplicate: number;
}

export interface LineStats {
  frames: number;
  garbage: number;
  bitFlips: number;
  duplicates: number;
}

export interface SerialFaultRelay {
  /** The pseudo-terminal the host should open. */
  path: string;
  toRobot: LineStats;
  toHost: LineStats;
  /**
   * Connects the relay to another robot pseudo-terminal (a restarted emulator), keeping the
   * host's: as a USB serial adapter stays while the board behind it reboots.
   */
  replaceRobot(robotPty: string): Promise<void>;
  close(): Promise<void>;
}

const SYNC = [0xa5, 0x5a];

export async function startSerialFaultRelay(options: {
  robotPty: string;
  seed: number;
  toRobot: LineFaults;
  toHost: LineFaults;
}): Promise<SerialFaultRelay> {
  const random = seededRandom(options.seed);
  const dir = mkdtempSync(join(tmpdir(), 'serial-relay-'));
  const path = join(dir, 'host-tty');
  const socat = spawn('socat', ['-d', '-d', `PTY,rawer,link=${path}`, 'STDIO'], {
    stdio: ['pipe', 'pipe', 'pipe'],
  });
  // a write racing socat's exit must not crash the test
  socat.stdin.on('error', () => undefined);
  const socatExited = new Promise<void>((resolve) => socat.once('exit', () => resolve()));
  await new Promise<void>((resolve, reject) => {
    let stderr = '';
    const timer = setTimeout(() => reject(new Error(`socat did not start: ${stderr}`)), 10_000);
    socat.stderr.on('data', (chunk: Buffer) => {
      stderr += chunk.toString();
      if (stderr.includes('starting data transfer loop')) {
        clearTimeout(timer);
        resolve();
      }
    });
    socat.once('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`socat exited (${code}): ${stderr}`));
    });
  });
  let robot = await openSerialPort(options.robotPty, 115200);

  const stats = (): LineStats => ({ frames: 0, garbage: 0, bitFlips: 0, duplicates: 0 });
  const toRobot = stats();
  const toHost = stats();
  let closed = false;

  const garbage = () =>
    Uint8Array.from({ length: 1 + Math.floor(random() * 32) }, () =>
      random() < 0.25 ? SYNC[Math.floor(random() * 2)]! : Math.floor(random() * 256),
    );

  /** Cuts a byte stream into frames and forwards each, damaged or not, with `send`. */
  const damager = (faults: LineFaults, s: LineStats, send: (bytes: Uint8Array) => void) => {
    // both ends write only whole, valid frames: anything else is dropped unreported
    const decoder = new FrameDecoder({
      onFrame: (type, seq, payload) => {
        s.frames += 1;
        const bytes = encodeFrame({ type, seq, payload });
        if (random() < faults.garbage) {
          s.garbage += 1;
          send(garbage());
        }
        const damaged = Uint8Array.from(bytes);
        if (random() < faults.bitFlip) {
          s.bitFlips += 1;
          const bit = Math.floor(random() * damaged.length * 8);
          damaged[bit >> 3]! ^= 1 << (bit & 7);
        }
        send(damaged);
        if (random() < faults.duplicate) {
          s.duplicates += 1;
          send(bytes);
        }
      },
    });
    return (chunk: Uint8Array) => {
      if (!closed) decoder.push(chunk);
    };
  };

  socat.stdout.on(
    'data',
    damager(options.toRobot, toRobot, (bytes) => {
      if (robot.isOpen) robot.write(bytes);
    }),
  );
  const attach = (port: SerialPortLike) => {
    const forward = damager(options.toHost, toHost, (bytes) => socat.stdin.write(bytes));
    port.on('data', (chunk) => {
      if (port === robot) forward(chunk);
    });
    // the robot's end going away (a killed emulator) is what some tests are about
    port.on('error', () => undefined);
  };
  attach(robot);

  return {
    path,
    toRobot,
    toHost,
    replaceRobot: async (robotPty) => {
      const old = robot;
      robot = await openSerialPort(robotPty, 115200);
      attach(robot);
      if (old.isOpen) await new Promise<void>((resolve) => old.close(() => resolve()));
    },
    close: async () => {
      if (closed) return;
      closed = true;
      if (robot.isOpen) await new Promise<void>((resolve) => robot.close(() => resolve()));
      socat.kill('SIGTERM');
      await socatExited;
      rmSync(dir, { recursive: true, force: true });
    },
  };
}
