import { describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';
import { waitForOutput } from '../wait-output.fixture.js';

describe('hal status', () => {
  it("prints the simulator's device, capabilities, pose, safety and health", async () => {
    const io = captureIO();
    expect(await runHal(['status', '--sim', '--map', 'room'], io)).toBe(0);
    const out = io.stdout();
    expect(out).toMatch(/^device {8}sim-robot-1 \(simulation, v1-stepper-cube\)$/m);
    expect(out).toMatch(/^capabilities .*locomotion\.differential:v1/m);
    expect(out).toMatch(/^pose {10}x -?\d+\.\d{3} m {2}y -?\d+\.\d{3} m {2}yaw -?\d+\.\d°/m);
    expect(out).toMatch(/^safety {8}ok$/m);
    expect(out).toMatch(/^health {8}ready, battery 100%, no errors$/m);
  });

  it('writes one JSON document with --json', async () => {
    const io = captureIO();
    expect(await runHal(['--json', 'status', '--sim'], io)).toBe(0);
    const [doc] = io.jsonLines() as Record<string, unknown>[];
    expect(doc).toMatchObject({
      device: { id: 'sim-robot-1', mode: 'simulation' },
      pose: { position: { x: 0, y: 0 } },
      safety: { emergencyStopped: false },
      health: { ready: true, batteryLevel: 100, errors: [] },
    });
    expect(doc!['capabilities']).toContain('safety.estop:v1.0');
    expect(io.jsonLines()).toHaveLength(1);
  });

  it('streams one JSON line per update with --watch until it is stopped', async () => {
    const io = captureIO();
    const run = runHal(['--json', 'status', '--sim', '--watch', '--rate', '20'], io);
    await waitForOutput(io, (o) => o.jsonLines().length >= 4);
    io.abort();
    expect(await run).toBe(0);
    const stamps = io.jsonLines().map((line) => (line as { ts: number }).ts);
    expect(stamps.length).toBeGreaterThanOrEqual(4);
    for (let i = 1; i < stamps.length; i += 1)
      expect(stamps[i]).toBeGreaterThanOrEqual(stamps[i - 1]!);
  });

  it('refuses a watch rate it cannot keep, before connecting', async () => {
    const io = captureIO();
    expect(await runHal(['status', '--sim', '--watch', '--rate', '500'], io)).toBe(2);
    expect(io.stderr()).toContain('"--rate" must be at most 50 Hz');
  });

  it('reports NOT_CONNECTED within the connect timeout when no robot answers', async () => {
    const io = captureIO();
    const started = Date.now();
    expect(
      await runHal(['--json', 'status', '--udp', '127.0.0.1:9', '--connect-timeout', '1000'], io),
    ).toBe(1);
    expect(JSON.parse(io.stderr())).toMatchObject({ error: { code: 'NOT_CONNECTED' } });
    expect(Date.now() - started).toBeLessThan(8000); // bounded: it did not hang
  }, 20_000);

  it('reports NOT_CONNECTED when the NATS server cannot be reached', async () => {
    const io = captureIO();
    expect(
      await runHal(['--json', 'status', '--device', 'cube-01', '--nats', 'nats://127.0.0.1:1'], io),
    ).toBe(1);
    expect(JSON.parse(io.stderr())).toMatchObject({
      error: { code: 'NOT_CONNECTED', message: expect.stringContaining('cannot reach NATS') },
    });
  }, 20_000);
});
