// PhysicalHAL's cost on the wire: a command round trip through PhysicalHAL (boundary, session,
// codec, UDP transport) against a raw dgram ping-pong with the same JSON, both to the same
// emulator in one run; then serial throughput over the emulator's pseudo-terminal, and the frame
// codec alone.
import { createSocket } from 'node:dgram';
import { decodeFrame, encodeFrame, FrameDecoder, PhysicalHAL } from '@hal/physical';
import { startEmulator } from '../tests/physical/emulator.js';

const ROUNDS = 2000;
const WARMUP = 200;

function percentile(samples: number[], p: number): number {
  const sorted = [...samples].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1)] ?? 0;
}

const fmt = (ms: number) => `${(ms * 1000).toFixed(0)} us`;

async function rawPingPong(port: number, rounds: number): Promise<number[]> {
  const socket = createSocket('udp4');
  await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
  let waiting: ((reply: Buffer) => void) | undefined;
  socket.on('message', (message) => waiting?.(message));
  const ask = (json: string) =>
    new Promise<Buffer>((resolve) => {
      waiting = resolve;
      socket.send(json, port, '127.0.0.1');
    });
  const hello = JSON.parse((await ask('{"cmd":"hello","seq":1}')).toString()) as { sid: number };
  const samples: number[] = [];
  for (let i = 0; i < rounds; i++) {
    const seq = i + 2;
    const json = `{"cmd":"set_led","seq":${seq},"sid":${hello.sid},"r":${i % 256},"g":0,"b":0,"pattern":"solid"}`;
    const start = performance.now();
    await ask(json);
    samples.push(performance.now() - start);
  }
  socket.close();
  return samples;
}

async function halRoundTrips(port: number, rounds: number): Promise<number[]> {
  const hal = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'bench',
    connection: { type: 'wifi', host: '127.0.0.1', udpPort: port },
  });
  await hal.initialize();
  const samples: number[] = [];
  for (let i = 0; i < rounds; i++) {
    const start = performance.now();
    const result = await hal.communication.setLED(i % 256, 0, 0, 'solid');
    samples.push(performance.now() - start);
    if (!result.success) throw new Error(`setLED failed: ${result.error}`);
  }
  await hal.cleanup();
  return samples;
}

async function serialThroughput(pty: string, seconds: number) {
  const hal = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'bench-serial',
    connection: { type: 'serial', port: pty, baudRate: 115200 },
  });
  await hal.initialize();
  const before = hal.linkStats()!;
  let requests = 0;
  const start = performance.now();
  while (performance.now() - start < seconds * 1000) {
    await hal.refreshStatus();
    requests += 1;
  }
  const elapsed = (performance.now() - start) / 1000;
  const after = hal.linkStats()!;
  await hal.cleanup();
  const frames =
    after.framesSent +
    after.framesReceived +
    after.acksSent +
    after.acksReceived -
    (before.framesSent + before.framesReceived + before.acksSent + before.acksReceived);
  return { requestsPerS: requests / elapsed, framesPerS: frames / elapsed };
}

/**
 * Frames/s of the two decoding paths over the same frames (a 60-byte payload), interleaved in
 * rounds: the streaming `FrameDecoder` (the path a serial link uses, fed in 64-byte chunks as a
 * port delivers them) and the one-shot `decodeFrame` of whole frames; encoding is included in both.
 */
function codecThroughput(): { streaming: number; oneShot: number } {
  const payload = new TextEncoder().encode(
    '{"seq":7,"sid":305419896,"ok":true,"cmd":"heartbeat","uptime_ms":1}',
  );
  const count = 50_000;
  const streamingRound = (): number => {
    const decoder = new FrameDecoder();
    const start = performance.now();
    let found = 0;
    const stream = new Uint8Array(64 * 1024);
    let filled = 0;
    for (let i = 0; i < count; i++) {
      const frame = encodeFrame({ type: 'data', seq: i & 0xffff, payload });
      if (filled + frame.length > stream.length) {
        for (let at = 0; at < filled; at += 64) {
          found += decoder.push(stream.subarray(at, Math.min(at + 64, filled))).length;
        }
        filled = 0;
      }
      stream.set(frame, filled);
      filled += frame.length;
    }
    for (let at = 0; at < filled; at += 64) {
      found += decoder.push(stream.subarray(at, Math.min(at + 64, filled))).length;
    }
    const seconds = (performance.now() - start) / 1000;
    if (found !== count) throw new Error(`streamed ${found} of ${count} frames`);
    return count / seconds;
  };
  const oneShotRound = (): number => {
    const start = performance.now();
    let found = 0;
    for (let i = 0; i < count; i++) {
      const frame = encodeFrame({ type: 'data', seq: i & 0xffff, payload });
      if (decodeFrame(frame).ok) found += 1;
    }
    const seconds = (performance.now() - start) / 1000;
    if (found !== count) throw new Error(`decoded ${found} of ${count} frames`);
    return count / seconds;
  };
  const streaming: number[] = [];
  const oneShot: number[] = [];
  for (let round = 0; round < 8; round++) {
    streaming.push(streamingRound());
    oneShot.push(oneShotRound());
  }
  return { streaming: percentile(streaming, 50), oneShot: percentile(oneShot, 50) };
}

const emulator = await startEmulator();
try {
  // warm both paths, then measure them interleaved in blocks so drift hits both alike
  await rawPingPong(emulator.udpPort, WARMUP);
  await halRoundTrips(emulator.udpPort, WARMUP);
  const raw: number[] = [];
  const hal: number[] = [];
  for (let block = 0; block < 4; block++) {
    raw.push(...(await rawPingPong(emulator.udpPort, ROUNDS / 4)));
    hal.push(...(await halRoundTrips(emulator.udpPort, ROUNDS / 4)));
  }
  const rawP50 = percentile(raw, 50);
  const rawP99 = percentile(raw, 99);
  const halP50 = percentile(hal, 50);
  const halP99 = percentile(hal, 99);
  console.log(`UDP round trip, ${ROUNDS} set_led commands each, emulator on 127.0.0.1:`);
  console.log(`  raw dgram ping-pong:  p50 ${fmt(rawP50)}  p99 ${fmt(rawP99)}`);
  console.log(`  PhysicalHAL.setLED:   p50 ${fmt(halP50)}  p99 ${fmt(halP99)}`);
  console.log(
    `  ratio HAL/raw:        p50 ${(halP50 / rawP50).toFixed(2)}x  p99 ${(halP99 / rawP99).toFixed(2)}x`,
  );
  const serial = await serialThroughput(emulator.pty, 3);
  console.log(
    `Serial over the emulator's pty: ${serial.requestsPerS.toFixed(0)} get_status round trips/s, ${serial.framesPerS.toFixed(0)} frames/s (DATA + ACK, both ways)`,
  );
  const codec = codecThroughput();
  console.log('Frame codec alone (encode + decode, median of 8 interleaved rounds):');
  console.log(
    `  streaming FrameDecoder, 64-byte chunks: ${(codec.streaming / 1000).toFixed(0)} k frames/s`,
  );
  console.log(
    `  one-shot decodeFrame, whole frames:     ${(codec.oneShot / 1000).toFixed(0)} k frames/s`,
  );
  console.log(
    `  ratio streaming/one-shot:               ${(codec.streaming / codec.oneShot).toFixed(2)}x`,
  );
} finally {
  await emulator.stop();
}
