// PhysicalHAL's cost on the wire: a command round trip through PhysicalHAL (boundary, session,
// codec, UDP transport) against a raw dgram ping-pong with the same JSON, both to the same
// emulator in one run; then serial throughput over the emulator's pseudo-terminal, and the frame
// codec alone.
import { createSocket } from 'node:dgram';
import { encodeFrame, FrameDecoder, PhysicalHAL } from '@hal/physical';
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

function codecThroughput(): number {
  const payload = new TextEncoder().encode(
    '{"seq":7,"sid":305419896,"ok":true,"cmd":"heartbeat","uptime_ms":1500,"running":false,"estop":false}',
  );
  const decoder = new FrameDecoder();
  const count = 200_000;
  let found = 0;
  const start = performance.now();
  for (let i = 0; i < count; i++) {
    const frame = encodeFrame({ type: 'data', seq: i & 0xffff, payload });
    found += decoder.push(frame).length;
  }
  const seconds = (performance.now() - start) / 1000;
  if (found !== count) throw new Error(`decoded ${found} of ${count} frames`);
  return count / seconds;
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
  console.log(
    `Frame codec alone (encode + decode): ${(codecThroughput() / 1000).toFixed(0)} k frames/s`,
  );
} finally {
  await emulator.stop();
}
