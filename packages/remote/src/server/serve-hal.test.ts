import { SimulationHAL } from '@hal/simulation';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { serveHal } from './index.js';
import type { HalServer } from './index.js';
import { TestClient } from './test-client.fixture.js';

let server: HalServer | undefined;
let sim: SimulationHAL | undefined;
const clients: TestClient[] = [];

async function rig(options: Parameters<typeof serveHal>[1] = {}) {
  // Real time, so a motion takes as long as on the robot (20 cm: about 4.5 s).
  sim = new SimulationHAL({ clock: 'realtime', realtimeSpeed: 1 });
  await sim.initialize();
  server = await serveHal(sim, { port: 0, ...options });
  return { sim, server };
}
async function client(headers?: Record<string, string>, url = server!.url): Promise<TestClient> {
  const c = await TestClient.connect(url, headers);
  clients.push(c);
  return c;
}

afterEach(async () => {
  await Promise.all(clients.splice(0).map((c) => c.close()));
  await server?.close();
  await sim?.cleanup();
  server = undefined;
  sim = undefined;
});

describe('serveHal', () => {
  describe('control', () => {
    it('makes the first client the controller and the next ones watchers', async () => {
      await rig();
      const first = await client();
      const second = await client();
      expect((await first.next('hal.remote.hello')).envelope.payload.role).toBe('controller');
      expect((await second.next('hal.remote.hello')).envelope.payload.role).toBe('watcher');
    });

    it('refuses motion, reset and LED from a watcher with NOT_CONTROLLER and lets it read', async () => {
      const { sim: hal } = await rig();
      await client();
      const watcher = await client();
      for (const [call, args] of [
        ['moveForward', [5]],
        ['drive', [100, 100, 200]],
        ['resetEmergencyStop', []],
        ['setLED', [1, 2, 3]],
      ] as const) {
        const reply = await watcher.reply(watcher.call(call, ...args));
        expect(reply.ok, call).toBe(false);
        if (!reply.ok) expect(reply.error.code).toBe('NOT_CONTROLLER');
      }
      const pose = await watcher.reply(watcher.call('getPose'));
      expect(pose).toMatchObject({ ok: true, value: { position: { x: 0, y: 0 } } });
      expect((await hal.locomotion.getPose()).position.x).toBe(0);
    });

    it('hands control over on take_control and tells the previous controller', async () => {
      await rig();
      const first = await client();
      const second = await client();
      second.send('hal.remote.take_control', { id: 'take' });
      expect(await second.reply('take')).toMatchObject({ ok: true, value: { role: 'controller' } });
      const told = await first.next('hal.remote.control');
      expect(told.envelope.payload.role).toBe('watcher');
      expect(told.envelope.payload.reason).toMatch(/taken/);
      const refused = await first.reply(first.call('moveForward', 1));
      expect(refused.ok === false && refused.error.code).toBe('NOT_CONTROLLER');
      const moved = await second.reply(second.call('moveForward', 1));
      expect(moved).toMatchObject({ ok: true, value: { success: true } });
    });
  });

  describe('emergency stop', () => {
    it('stops a long move at once when a watcher sends it, without waiting for the move', async () => {
      const { sim: hal } = await rig();
      const controller = await client();
      const watcher = await client();
      const move = controller.call('moveForward', 20);
      await new Promise((r) => setTimeout(r, 300));
      const started = Date.now();
      const stop = await watcher.reply(watcher.call('emergencyStop', 'watcher saw a cliff'));
      const elapsed = Date.now() - started;
      expect(stop).toMatchObject({
        ok: true,
        value: { success: true },
        safety: { emergencyStopped: true },
      });
      // The move alone would take over 4 s more: the stop did not wait behind it.
      expect(elapsed).toBeLessThan(2000);
      const moved = await controller.reply(move, 10_000);
      expect(moved.ok && (moved.value as { success: boolean }).success).toBe(false);
      expect((await hal.locomotion.getPose()).position.x).toBeLessThan(0.1);
      expect(hal.safety.isEmergencyStopped()).toBe(true);
    });

    it('stops a long move at once when the controller itself sends it on the same socket', async () => {
      const { sim: hal } = await rig();
      const controller = await client();
      const move = controller.call('moveForward', 20);
      await new Promise((r) => setTimeout(r, 300));
      const started = Date.now();
      const stop = await controller.reply(controller.call('emergencyStop'));
      expect(Date.now() - started).toBeLessThan(2000);
      expect(stop).toMatchObject({ ok: true, value: { success: true } });
      const moved = await controller.reply(move, 10_000);
      expect(moved.ok && (moved.value as { success: boolean }).success).toBe(false);
      expect((await hal.locomotion.getPose()).position.x).toBeLessThan(0.1);
    });

    it('passes any reason, even one the e-stop schema would refuse, to the HAL', async () => {
      const { sim: hal } = await rig();
      await client();
      const watcher = await client();
      const emergencyStop = vi.spyOn(hal.safety, 'emergencyStop');
      await watcher.reply(watcher.call('emergencyStop', 42));
      await watcher.reply(watcher.call('emergencyStop', 'x'.repeat(500)));
      expect(emergencyStop.mock.calls).toEqual([[42], ['x'.repeat(500)]]);
    });
  });

  describe('a controller that vanishes', () => {
    it('has its motion stopped when its socket is destroyed mid-move', async () => {
      const { sim: hal } = await rig({ heartbeatTimeoutMs: 1000 });
      const stop = vi.spyOn(hal.locomotion, 'stop');
      const controller = await client();
      controller.call('drive', 200, 200);
      await vi.waitFor(
        async () => expect((await hal.locomotion.getPose()).velocity.linear).toBeGreaterThan(0),
        { timeout: 3000 },
      );
      controller.socket.terminate();
      await vi.waitFor(() => expect(stop).toHaveBeenCalled(), { timeout: 1000 });
      await vi.waitFor(
        async () => expect((await hal.locomotion.getPose()).velocity.linear).toBe(0),
        { timeout: 1000 },
      );
    });

    it('has its motion stopped within the heartbeat timeout when it goes silent', async () => {
      const { sim: hal } = await rig({ heartbeatTimeoutMs: 500 });
      const stop = vi.spyOn(hal.locomotion, 'stop');
      const controller = await client();
      const move = controller.call('moveForward', 20);
      const started = Date.now();
      await vi.waitFor(() => expect(stop).toHaveBeenCalled(), { timeout: 3000, interval: 10 });
      // 500 ms timeout plus the watchdog's 100 ms period; generous headroom for a loaded machine.
      expect(Date.now() - started).toBeLessThan(2000);
      expect(Date.now() - started).toBeGreaterThanOrEqual(450);
      await vi.waitFor(
        async () => expect((await hal.locomotion.getPose()).velocity.linear).toBe(0),
        { timeout: 1000 },
      );
      expect((await hal.locomotion.getPose()).position.x).toBeLessThan(0.1);
      expect(
        controller.messages.some(
          (m) => m.schema === 'hal.remote.reply' && m.envelope.payload.id === move,
        ),
      ).toBe(false);
    });

    it('keeps a controller that sends heartbeats', async () => {
      const { sim: hal } = await rig({ heartbeatTimeoutMs: 300 });
      const stop = vi.spyOn(hal.locomotion, 'stop');
      const controller = await client();
      const beat = setInterval(() => controller.send('hal.remote.heartbeat', {}), 75);
      await new Promise((r) => setTimeout(r, 900));
      clearInterval(beat);
      expect(stop).not.toHaveBeenCalled();
      expect(controller.open).toBe(true);
    });
  });

  describe('bad messages', () => {
    const cases: Array<[string, (c: TestClient) => string | null, string]> = [
      ['text that is not JSON', (c) => (c.raw('{nope'), null), 'MALFORMED'],
      [
        'JSON that is not an envelope',
        (c) => (c.raw(JSON.stringify({ payload: { id: 'x1' } })), 'x1'),
        'MALFORMED',
      ],
      ['an unknown call', (c) => c.call('selfDestruct'), 'UNKNOWN_COMMAND'],
      [
        'a message only a server sends',
        (c) => (
          c.send('hal.remote.state', {
            pose: null,
            moving: false,
            safety: { emergencyStopped: false, batteryLevel: 1, errors: [] },
            role: 'watcher',
          }),
          null
        ),
        'MALFORMED',
      ],
      ['a binary frame', (c) => (c.raw(Buffer.from([1, 2, 3])), null), 'MALFORMED'],
    ];
    for (const [what, send, code] of cases) {
      it(`answers ${what} with a ${code} error, keeps the connection and moves nothing`, async () => {
        const { sim: hal } = await rig();
        const c = await client();
        const id = send(c);
        const reply = (await c.next('hal.remote.reply', (m) => !m.envelope.payload.ok)).envelope
          .payload;
        expect(reply.ok === false && reply.error.code).toBe(code);
        expect(reply.id).toBe(id);
        expect(c.open).toBe(true);
        expect(await c.reply(c.call('getPose'))).toMatchObject({ ok: true });
        expect((await hal.locomotion.getPose()).position.x).toBe(0);
      });
    }

    it("answers bad arguments with the HAL's own refusal naming the parameter", async () => {
      await rig();
      const c = await client();
      const reply = await c.reply(c.call('moveForward', Number.NaN));
      expect(reply).toMatchObject({
        ok: true,
        value: { success: false, code: 'INVALID_PARAMETER' },
      });
      expect(JSON.stringify(reply)).toContain('distanceCm');
    });

    it('answers an oversized message with MALFORMED and keeps the connection', async () => {
      await rig({ maxMessageBytes: 1024 });
      const c = await client();
      const id = c.call('log', 'x'.repeat(2000));
      const reply = await c.reply(id);
      expect(reply.ok === false && reply.error.message).toMatch(/over the 1024-byte limit/);
      expect(await c.reply(c.call('isEmergencyStopped'))).toMatchObject({ ok: true, value: false });
    });
  });

  describe('state stream', () => {
    it('streams pose, motion and safety to subscribers at the set rate', async () => {
      await rig({ stateRateHz: 20 });
      const c = await client();
      c.send('hal.remote.subscribe', { state: true });
      await new Promise((r) => setTimeout(r, 600));
      const states = c.messages.filter((m) => m.schema === 'hal.remote.state');
      expect(states.length).toBeGreaterThanOrEqual(4);
      expect(states.length).toBeLessThanOrEqual(14);
      expect(states[0]!.envelope.payload).toMatchObject({
        moving: false,
        role: 'controller',
        safety: { emergencyStopped: false },
      });
    });
  });

  describe('security', () => {
    it('refuses to bind beyond loopback without a token, saying so', async () => {
      const hal = new SimulationHAL();
      await expect(serveHal(hal, { host: '0.0.0.0', port: 0 })).rejects.toThrow(/needs a token/);
    });

    it('refuses a connection without the token, and accepts a Bearer header or a token parameter', async () => {
      const token = 'a-long-enough-secret-token';
      await rig({ token });
      await expect(client()).rejects.toThrow();
      await expect(
        client({ authorization: 'Bearer wrong-token-of-some-length' }),
      ).rejects.toThrow();
      const header = await client({ authorization: `Bearer ${token}` });
      expect(header.open).toBe(true);
      const query = await client({}, `${server!.url}/?token=${token}`);
      expect(query.open).toBe(true);
    });
  });
});
