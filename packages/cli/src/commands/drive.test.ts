import { RemoteHAL } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import type { HalServer } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';
import { waitForOutput } from '../wait-output.fixture.js';

interface DriveDoc {
  result: { success: boolean; mode: string };
  pose: { position: { x: number; y: number }; rotation: { yaw: number } };
  stoppedByUser: boolean;
}

async function drive(...argv: string[]): Promise<DriveDoc> {
  const io = captureIO();
  const code = await runHal(['--json', 'drive', ...argv], io);
  expect(code, io.stderr()).toBe(0);
  return io.jsonLines()[0] as DriveDoc;
}

describe('hal drive on the embedded simulator', () => {
  const fast = ['--sim', '--time-scale', '20'];

  it('drives forward and back in metres', async () => {
    expect((await drive('forward', '0.1', ...fast)).pose.position.x).toBeCloseTo(0.1, 3);
    expect((await drive('forward', '-0.05', ...fast)).pose.position.x).toBeCloseTo(-0.05, 3);
  });

  it('turns counter-clockwise for positive degrees (REP-103) and clockwise for negative', async () => {
    expect((await drive('turn', '90', ...fast)).pose.rotation.yaw).toBeCloseTo(Math.PI / 2, 2);
    expect((await drive('turn', '-90', ...fast)).pose.rotation.yaw).toBeCloseTo(-Math.PI / 2, 2);
  });

  it('moves to a point and drives the wheels for a duration', async () => {
    const to = await drive('move-to', '0.1', '0.1', ...fast);
    expect(to.pose.position.x).toBeCloseTo(0.1, 2);
    expect(to.pose.position.y).toBeCloseTo(0.1, 2);
    const wheels = await drive('wheels', '255', '255', '--duration', '4000', ...fast);
    expect(wheels.result.success).toBe(true);
    expect(wheels.pose.position.x).toBeGreaterThan(0.05);
  });

  it("refuses a move-to beyond the simulated arena's walls, naming the limit, and moves nothing", async () => {
    const io = captureIO();
    // without the guard, which would first turn to face the point and look (docs/tools.md)
    expect(await runHal(['drive', 'move-to', '10', '10', '--no-guard', ...fast], io)).toBe(1);
    expect(io.stderr()).toMatch(
      /hal: RANGE_EXCEEDED: moveTo target \(10, 10\) m is outside the 5 x 5 m arena: .*x within -2\.43\.\.2\.43 m/,
    );
    expect(io.stderr()).not.toMatch(/x \d+\.\d{3} m/); // no live pose: nothing moved
  });

  it('prints the result and the pose for people', async () => {
    const io = captureIO();
    expect(await runHal(['drive', 'forward', '0.02', ...fast], io)).toBe(0);
    expect(io.stdout()).toMatch(
      /^forward 0\.02 m: ok in \d+\.\d\d s \(simulation\)\npose x 0\.020 m/,
    );
    // a distance may carry its unit: 2cm is the 0.02 m a bare 0.02 means
    const cm = captureIO();
    expect(await runHal(['drive', 'forward', '2cm', ...fast], cm)).toBe(0);
    expect(cm.stdout()).toMatch(/^forward 0\.02 m: ok/);
    // a negative one goes after -- (commander takes -2cm for an option), and says so if not
    const back = captureIO();
    expect(await runHal(['drive', 'forward', ...fast, '--', '-2cm'], back)).toBe(0);
    expect(back.stdout()).toMatch(/^forward -0\.02 m: ok/);
    const hint = captureIO();
    expect(await runHal(['drive', 'forward', '-2cm', ...fast], hint)).toBe(2);
    expect(hint.stderr()).toContain(
      "hal: USAGE: unknown option '-2cm' (a negative value with a unit goes after --: ... -- -2cm)",
    );
  });

  it.each([
    [
      ['forward', 'NaN'],
      /"distance" must be a distance: metres, or with a unit: 0\.3m, 30cm, 300mm; got "NaN"/,
    ],
    [['forward', '12abc'], /"distance" must be a distance/],
    [['forward', '5deg'], /"distance" must be a distance/],
    [['forward', '500cm'], /forward: distance 5 m is above the limit 1\.884 m$/m],
    [['forward', '0'], /forward: the distance must not be 0/],
    [['forward', '5'], /forward: distance 5 m is above the limit 1\.884 m$/m],
    [['forward', '-5'], /forward: distance -5 m is below the limit -1\.884 m$/m],
    [['turn', '-3000'], /turn: angle -3000° is below the limit -2159\.9°$/m],
    [['turn', 'Infinity'], /"angle" must be an angle: degrees, or with a unit: 90deg, 1\.5rad/],
    [['turn', '90cm'], /"angle" must be an angle/],
    [['move-to', '1', 'x'], /"y" must be a distance/],
    [['move-to', '100', '0'], /move-to: x 100 m is above the limit 50 m$/m],
    [['wheels', '300', '0'], /wheels: left power 300 is above the limit 255$/m],
    [['wheels', '100', '100', '--duration', '-5'], /wheels: duration -5 ms must be above 0 ms$/m],
    [['estop', 'a', 'b'], /too many arguments/],
  ])('refuses %j as a usage error before connecting to anything', async (argv, message) => {
    const io = captureIO();
    // a robot address nothing answers at: a connection attempt would end NOT_CONNECTED instead
    expect(await runHal(['drive', ...argv, '--udp', '127.0.0.1:9'], io)).toBe(2);
    expect(io.stderr()).toMatch(message);
    expect(io.stderr()).not.toContain('NOT_CONNECTED');
  });
});

describe('hal drive on a served simulator (--ws)', () => {
  let sim: SimulationHAL;
  let server: HalServer;

  beforeEach(async () => {
    sim = new SimulationHAL({ clock: 'realtime' });
    await sim.initialize();
    server = await serveHal(sim, { port: 0 });
  });
  afterEach(async () => {
    await server.close();
    await sim.cleanup();
  });

  it('stops the robot when interrupted during a motion, and exits 130', async () => {
    const io = captureIO();
    const run = runHal(['drive', 'forward', '0.5', '--ws', server.url], io);
    await waitForOutput(io, (o) => o.stderr().includes(' m/s'));
    io.abort();
    expect(await run).toBe(130);
    expect(io.stderr()).toContain('interrupted: the robot was stopped');
    const stoppedAt = (await sim.locomotion.getPose()).position.x;
    expect(stoppedAt).toBeGreaterThan(0);
    expect(stoppedAt).toBeLessThan(0.3);
    await new Promise((resolve) => setTimeout(resolve, 300));
    expect((await sim.locomotion.getPose()).position.x).toBe(stoppedAt);
  });

  it('drives the wheels until interrupted when no duration is given, then stops them', async () => {
    const io = captureIO();
    const run = runHal(['--json', 'drive', 'wheels', '200', '200', '--ws', server.url], io);
    const deadline = Date.now() + 10_000;
    while ((await sim.locomotion.getPose()).velocity.linear <= 0 && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    expect((await sim.locomotion.getPose()).velocity.linear).toBeGreaterThan(0);
    await new Promise((resolve) => setTimeout(resolve, 300));
    io.abort();
    expect(await run).toBe(0);
    expect((io.jsonLines()[0] as DriveDoc).stoppedByUser).toBe(true);
    const pose = await sim.locomotion.getPose();
    expect(pose.position.x).toBeGreaterThan(0);
    expect(pose.velocity.linear).toBe(0);
  });

  it('latches the e-stop with its reason, refuses motion while latched, and resets it', async () => {
    const estop = captureIO();
    expect(await runHal(['drive', 'estop', 'bumper hit', '--ws', server.url], estop)).toBe(0);
    expect(sim.safety.isEmergencyStopped()).toBe(true);
    expect(sim.safety.getSafetyStatus().emergencyStopReason).toBe('bumper hit');
    const refused = captureIO();
    expect(await runHal(['--json', 'drive', 'forward', '0.1', '--ws', server.url], refused)).toBe(
      1,
    );
    expect(JSON.parse(refused.stderr())).toMatchObject({ error: { code: 'EMERGENCY_STOPPED' } });
    expect((await sim.locomotion.getPose()).position.x).toBe(0);
    const reset = captureIO();
    expect(await runHal(['drive', 'reset-estop', '--ws', server.url], reset)).toBe(0);
    expect(sim.safety.isEmergencyStopped()).toBe(false);
  });
  it('never takes control from another client: motion is NOT_CONTROLLER, an e-stop still lands', async () => {
    const other = new RemoteHAL({ url: server.url, reconnect: false });
    await other.initialize();
    try {
      expect(other.role).toBe('controller');
      const refused = captureIO();
      const argv = ['--json', 'drive', 'forward', '0.1', '--ws', server.url];
      expect(await runHal([...argv, '--connect-timeout', '1000'], refused)).toBe(1);
      expect(JSON.parse(refused.stderr())).toMatchObject({ error: { code: 'NOT_CONTROLLER' } });
      expect(other.role).toBe('controller');
      const estop = captureIO();
      expect(await runHal(['drive', 'estop', 'from a watcher', '--ws', server.url], estop)).toBe(0);
      expect(sim.safety.isEmergencyStopped()).toBe(true);
    } finally {
      await other.cleanup();
    }
  });
});
