import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { readRecordingFile } from '@hal/recorder';
import { describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';
import { waitForOutput } from '../wait-output.fixture.js';

describe('hal serve on WebSocket', () => {
  it('serves the simulator until stopped, and hal status --ws reads it', async () => {
    const io = captureIO();
    const serving = runHal(
      ['--json', 'serve', '--sim', '--device', 'desk-sim', '--ws-port', '0'],
      io,
    );
    await waitForOutput(io, (o) => o.jsonLines().length > 0);
    const first = io.jsonLines()[0] as { event: string; device: string; ws: { url: string } };
    expect(first).toMatchObject({ event: 'serving', device: 'desk-sim', mode: 'simulation' });
    expect(first.ws.url).toMatch(/^ws:\/\/127\.0\.0\.1:\d+$/);

    const status = captureIO();
    expect(await runHal(['--json', 'status', '--ws', first.ws.url], status)).toBe(0);
    expect(status.jsonLines()[0]).toMatchObject({
      device: { id: 'desk-sim', mode: 'simulation' },
      health: { ready: true },
    });
    const moved = captureIO();
    expect(await runHal(['drive', 'turn', '5', '--ws', first.ws.url], moved)).toBe(0);

    io.abort();
    expect(await serving).toBe(0);
    expect(io.jsonLines().at(-1)).toEqual({ event: 'stopped' });
    // it no longer listens
    const gone = captureIO();
    expect(await runHal(['status', '--ws', first.ws.url, '--connect-timeout', '2000'], gone)).toBe(
      1,
    );
    expect(gone.stderr()).toContain('NOT_CONNECTED');
  }, 30_000);

  it('requires the token from $HAL_SERVE_TOKEN, and hal status --ws presents it the same way', async () => {
    const env = { HAL_SERVE_TOKEN: 'a-token-of-24-characters' };
    const io = captureIO(env);
    const serving = runHal(['--json', 'serve', '--sim', '--ws-port', '0'], io);
    await waitForOutput(io, (o) => o.jsonLines().length > 0);
    const { ws } = io.jsonLines()[0] as { ws: { url: string } };
    const refused = captureIO();
    expect(await runHal(['status', '--ws', ws.url], refused)).toBe(1);
    expect(refused.stderr()).toContain(
      `AUTH_FAILED: ${ws.url} refused the connection (HTTP 401): no token was given`,
    );
    const admitted = captureIO(env);
    expect(await runHal(['status', '--ws', ws.url], admitted), admitted.stderr()).toBe(0);
    const byOption = captureIO();
    expect(await runHal(['status', '--ws', ws.url, '--token', env.HAL_SERVE_TOKEN], byOption)).toBe(
      0,
    );
    io.abort();
    expect(await serving).toBe(0);
  }, 30_000);

  it('prints where it listens for people', async () => {
    const io = captureIO();
    const serving = runHal(['serve', '--sim', '--ws-port', '0'], io);
    await waitForOutput(io, (o) => o.stdout().includes('listening'));
    io.abort();
    expect(await serving).toBe(0);
    expect(io.stdout()).toMatch(
      /^serving sim-robot-1 \(simulation\)\n {2}listening ws:\/\/127\.0\.0\.1:\d+\n/,
    );
  });

  it.each([
    [['serve', '--sim'], 2, /say where to serve: --nats <servers>/],
    [['serve', '--ws-port', '0'], 2, /name the robot: one of --sim, --udp, --serial$/m],
    [
      ['serve', '--sim', '--nats', 'nats://127.0.0.1:1', '--host', '0.0.0.0'],
      2,
      /"--host" needs --ws-port/,
    ],
    [
      ['serve', '--sim', '--nats', 'nats://127.0.0.1:1', '--token', 'a-token-of-16-chars'],
      2,
      /"--token" needs --ws-port/,
    ],
    [
      ['serve', '--sim', '--nats', 'nats://127.0.0.1:1', '--state-rate', '5'],
      2,
      /"--state-rate" on NATS is 10..100 Hz/,
    ],
    [['serve', '--sim', '--ws', 'ws://a'], 2, /unknown option '--ws'/],
    [
      ['serve', '--sim', '--ws-port', '0', '--no-default-device'],
      2,
      /"--no-default-device" needs --nats/,
    ],
    [['serve', '--sim', '--ws-port', '0', '--host', '0.0.0.0'], 1, /not loopback\) needs a token/],
  ])('refuses %j with a clear error', async (argv, code, message) => {
    const io = captureIO();
    expect(await runHal(argv, io)).toBe(code);
    expect(io.stderr()).toMatch(message);
  });

  it('says NOT_CONNECTED, and lets the robot go, when NATS cannot be reached', async () => {
    const io = captureIO();
    expect(await runHal(['--json', 'serve', '--sim', '--nats', 'nats://127.0.0.1:1'], io)).toBe(1);
    expect(JSON.parse(io.stderr())).toMatchObject({ error: { code: 'NOT_CONNECTED' } });
  });
});

describe('hal serve --record', () => {
  it("records every client's calls into the file, and says what it wrote when stopped", async () => {
    const dir = mkdtempSync(join(tmpdir(), 'hal-serve-record-'));
    try {
      const file = join(dir, 'served.mcap');
      const io = captureIO();
      const serving = runHal(
        ['--json', 'serve', '--sim', '--time-scale', '20', '--ws-port', '0', '--record', file],
        io,
      );
      await waitForOutput(io, (o) => o.jsonLines().length > 0);
      const { ws } = io.jsonLines()[0] as { ws: { url: string } };
      expect(await runHal(['drive', 'forward', '0.05', '--ws', ws.url], captureIO())).toBe(0);
      expect(await runHal(['drive', 'estop', 'served', '--ws', ws.url], captureIO())).toBe(0);
      io.abort();
      expect(await serving).toBe(0);
      expect(io.jsonLines().at(-1)).toMatchObject({
        event: 'stopped',
        recording: { file, dropped: 0, written: expect.any(Number) },
      });
      const recording = await readRecordingFile(file);
      expect(recording.complete).toBe(true);
      const calls = recording.messages
        .filter((m) => m.topic === '/hal/calls')
        .map((m) => (m.value as { call: string }).call);
      expect(calls).toContain('locomotion.moveForward');
      expect(calls).toContain('safety.emergencyStop');
      expect(recording.metadata.get('hal.robot')).toMatchObject({ mode: 'simulation' });
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  }, 30_000);

  it('refuses a file it cannot write before touching the robot', async () => {
    const io = captureIO();
    const code = await runHal(
      ['serve', '--sim', '--ws-port', '0', '--record', '/nonexistent-dir/run.mcap'],
      io,
    );
    expect(code).toBe(2);
    expect(io.stderr()).toContain(
      'hal: USAGE: "--record" /nonexistent-dir/run.mcap: its folder /nonexistent-dir does not exist',
    );
  });
});
