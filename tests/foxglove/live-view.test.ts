// The live view as Foxglove sees it: the real `@foxglove/ws-protocol` client subscribes,
// receives each topic at its rate, teleops within the leash and is refused beyond it, calls the
// e-stop; the door refuses foreign pages and wrong tokens; a viewer that cannot keep up loses
// messages, counted, while the others do not.
import { serveFoxglove } from '@hal/foxglove';
import type { FoxgloveLiveServer } from '@hal/foxglove';
import { OccupancyGrid } from '@hal/navigation';
import { Perception } from '@hal/perception';
import { SimulationHAL } from '@hal/simulation';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { connectViewer } from './viewer.js';
import type { Viewer } from './viewer.js';

let hal: SimulationHAL;
let server: FoxgloveLiveServer | undefined;
const viewers: Viewer[] = [];

beforeEach(async () => {
  hal = new SimulationHAL({ deviceId: 'sim-1' });
  await hal.initialize();
});

afterEach(async () => {
  for (const v of viewers.splice(0)) v.close();
  await server?.close();
  server = undefined;
  await hal.cleanup();
});

async function viewerOf(url: string, headers?: Record<string, string>): Promise<Viewer> {
  const viewer = await connectViewer(url, headers);
  viewers.push(viewer);
  return viewer;
}

describe('topics', () => {
  it('advertises the recorder topics with their Foxglove schemas, and the control services', async () => {
    server = await serveFoxglove(hal, { port: 0 });
    const viewer = await viewerOf(server.url);
    const schemas = Object.fromEntries(viewer.channels.map((c) => [c.topic, c.schemaName]));
    expect(schemas).toEqual({
      '/hal/pose': 'foxglove.PoseInFrame',
      '/tf': 'foxglove.FrameTransform',
      '/hal/pose/raw': 'hal.Pose',
      '/hal/log': 'foxglove.Log',
      '/hal/safety': 'hal.SafetyEvent',
      '/hal/camera': 'foxglove.CompressedImage',
    });
    expect(viewer.channels.every((c) => c.encoding === 'json')).toBe(true);
    expect(viewer.services.map((s) => s.name).sort()).toEqual([
      '/hal/emergency_stop',
      '/hal/reset_emergency_stop',
      '/hal/stop',
    ]);
    expect(viewer.info.capabilities).toEqual(['clientPublish', 'services']);
    expect(viewer.info.supportedEncodings).toEqual(['json']);
  });

  it('sends each topic at its rate: pose and /tf at the pose rate, the camera at its own', async () => {
    server = await serveFoxglove(hal, { port: 0, poseRateHz: 20, cameraRateHz: 4 });
    const viewer = await viewerOf(server.url);
    await viewer.subscribe('/hal/pose', '/tf', '/hal/camera');
    await viewer.until(() => viewer.on('/hal/pose').length >= 40);
    const poses = viewer.on('/hal/pose');
    const tfs = viewer.on('/tf');
    const frames = viewer.on('/hal/camera');
    // the window the poses span, by the messages' own times (no wall-clock pass or fail)
    const windowS = Number(poses.at(-1)!.at - poses[0]!.at) / 1e9;
    expect(poses.length / windowS).toBeGreaterThan(20 * 0.4);
    expect(poses.length / windowS).toBeLessThan(20 * 1.5);
    // the camera at 4 Hz beside the pose at 20: a fifth as many, generously
    expect(frames.length).toBeGreaterThanOrEqual(Math.floor(poses.length * 0.05));
    expect(frames.length).toBeLessThanOrEqual(Math.ceil(poses.length * 0.4));
    expect(Math.abs(tfs.length - poses.length)).toBeLessThanOrEqual(2);
    expect(tfs[0]!.value).toMatchObject({ parent_frame_id: 'world', child_frame_id: 'base_link' });
    expect(frames[0]!.value).toMatchObject({ frame_id: 'camera', format: 'jpeg' });
    expect(String(frames[0]!.value['data']).length).toBeGreaterThan(100);
  });

  it('shows log lines and e-stops made through its HAL by others, and a trip made elsewhere', async () => {
    server = await serveFoxglove(hal, { port: 0 });
    const viewer = await viewerOf(server.url);
    await viewer.subscribe('/hal/log', '/hal/safety');
    await server.hal.communication.log('hello from the agent', 'warn');
    await viewer.until(() =>
      viewer.on('/hal/log').some((m) => m.value['message'] === 'hello from the agent'),
    );
    const line = viewer.on('/hal/log').find((m) => m.value['message'] === 'hello from the agent');
    expect(line!.value).toMatchObject({ level: 3, name: 'sim-1' });
    await server.hal.safety.emergencyStop('agent pressed it');
    await viewer.until(() => viewer.on('/hal/safety').length >= 1);
    expect(viewer.on('/hal/safety')[0]!.value).toEqual({
      event: 'emergency_stop',
      reason: 'agent pressed it',
      success: true,
      emergency_stopped: true,
    });
    // a reset on the robot itself, not through the view: the latch is seen to clear
    await hal.safety.resetEmergencyStop();
    await viewer.until(() => viewer.on('/hal/safety').length >= 2);
    expect(viewer.on('/hal/safety')[1]!.value).toMatchObject({
      event: 'cleared',
      emergency_stopped: false,
    });
  });
});

describe('perception', () => {
  it('shows each look: its detections and remembered objects as SceneUpdates, and the grid', async () => {
    const perception = new Perception(hal, { grid: new OccupancyGrid({ widthM: 2, heightM: 2 }) });
    server = await serveFoxglove(hal, { port: 0, perception });
    const viewer = await viewerOf(server.url);
    const schemas = Object.fromEntries(viewer.channels.map((c) => [c.topic, c.schemaName]));
    expect(schemas).toMatchObject({
      '/perception/detections': 'foxglove.SceneUpdate',
      '/perception/objects': 'foxglove.SceneUpdate',
      '/perception/grid': 'foxglove.Grid',
    });
    await viewer.subscribe(
      ...viewer.channels.map((c) => c.topic).filter((t) => t.startsWith('/perception/')),
    );
    await perception.look();
    await viewer.until(() => viewer.on('/perception/objects').length >= 1);
    expect(viewer.on('/perception/detections')).toHaveLength(1);
    expect(viewer.on('/perception/objects')[0]!.value).toHaveProperty('entities');
    // the look laid free space into the grid: the grid, changed, follows
    await viewer.until(() => viewer.on('/perception/grid').length >= 1);
    expect(viewer.on('/perception/grid')[0]!.value).toMatchObject({ frame_id: 'world' });
  });
});

describe('teleop and services', () => {
  const twist = (x: number, z = 0) => ({
    linear: { x, y: 0, z: 0 },
    angular: { x: 0, y: 0, z },
  });

  it('drives within the leash, refuses beyond it, and the e-stop always goes', async () => {
    // the V1 robot's top speed is 0.047 m/s; the leash allows 0.03
    server = await serveFoxglove(hal, { port: 0, leash: { maxSpeedMPerS: 0.03 } });
    const viewer = await viewerOf(server.url);
    const publish = viewer.publisher('/cmd_vel', 'geometry_msgs/Twist');
    const live = server;
    const start = await hal.locomotion.getPose();

    publish(twist(0.02));
    await viewer.until(() => live.stats().teleop.driven >= 1);
    const moved = await hal.locomotion.getPose();
    expect(moved.position.x - start.position.x).toBeGreaterThan(0.001);

    publish(twist(0.045));
    await viewer.until(() => viewer.statuses.some((s) => s.message.includes('LEASH_SPEED')));
    expect(live.stats().teleop.refused).toBe(1);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(moved.position.x, 6);

    const stopped = await viewer.call('/hal/emergency_stop', { reason: 'from foxglove' });
    expect(stopped).toEqual({ success: true, emergency_stopped: true });
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    publish(twist(0.02));
    await viewer.until(() => live.stats().teleop.refused >= 2);
    expect(viewer.statuses.at(-1)!.message).toMatch(/EMERGENCY_STOP/);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(moved.position.x, 6);

    expect(await viewer.call('/hal/reset_emergency_stop')).toMatchObject({
      success: true,
      emergency_stopped: false,
    });
    expect(await viewer.call('/hal/stop')).toMatchObject({ success: true });
  });

  it('lets a viewer that joined with ?role=watch stop the robot, not drive it', async () => {
    server = await serveFoxglove(hal, { port: 0 });
    const viewer = await viewerOf(`${server.url}/?role=watch`);
    const publish = viewer.publisher('/cmd_vel', 'geometry_msgs/Twist');
    const start = await hal.locomotion.getPose();
    publish(twist(0.02));
    await viewer.until(() => viewer.statuses.length > 0);
    expect(viewer.statuses[0]!.message).toMatch(/NOT_CONTROLLER.*role=watch/);
    expect((await hal.locomotion.getPose()).position.x).toBe(start.position.x);
    expect(await viewer.call('/hal/emergency_stop')).toMatchObject({ success: true });
  });

  it('stops the robot for a viewer that leaves while its drive runs', async () => {
    const lines: string[] = [];
    const logger = { log: (_level: string, _ns: string, message: string) => lines.push(message) };
    // a drive of 2 s: the viewer leaves long before it ends
    server = await serveFoxglove(hal, { port: 0, teleopHoldMs: 2000, logger });
    const viewer = await viewerOf(server.url);
    const publish = viewer.publisher('/cmd_vel', 'geometry_msgs/Twist');
    publish(twist(0.02));
    // a round trip after the message: the server has taken it
    await viewer.subscribe('/hal/pose');
    viewer.close();
    await viewer.until(() => lines.some((l) => l.includes('left while driving')));
    expect(lines).toContain('viewer-1 left while driving: stopping the robot');
  });

  it('refuses a teleop message that is no Twist, with a status saying what one is', async () => {
    server = await serveFoxglove(hal, { port: 0 });
    const viewer = await viewerOf(server.url);
    const publish = viewer.publisher('/cmd_vel', 'geometry_msgs/Twist');
    publish({ linear: { x: 'fast' } });
    await viewer.until(() => viewer.statuses.length > 0);
    expect(viewer.statuses[0]!.message).toMatch(/INVALID_PARAMETER.*geometry_msgs\/Twist/);
  });
});

describe('the door', () => {
  it('refuses a page from a foreign origin, lets the desktop apps and trusted origins in', async () => {
    server = await serveFoxglove(hal, {
      port: 0,
      allowedOrigins: ['https://app.foxglove.dev'],
    });
    await expect(connectViewer(server.url, { Origin: 'https://evil.example' })).rejects.toThrow(
      'HTTP 403',
    );
    // a sandboxed or file page's `null` is not the desktop app's file://
    await expect(connectViewer(server.url, { Origin: 'null' })).rejects.toThrow('HTTP 403');
    for (const origin of ['https://app.foxglove.dev', 'file://', 'http://localhost:5173']) {
      const viewer = await viewerOf(server.url, { Origin: origin });
      expect(viewer.channels.length).toBeGreaterThan(0);
    }
  });

  it('refuses to serve beyond loopback without a token, and with one wants it presented', async () => {
    await expect(serveFoxglove(hal, { host: '0.0.0.0', port: 0 })).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
    });
    const token = 'a-long-enough-token';
    server = await serveFoxglove(hal, { port: 0, token });
    await expect(connectViewer(server.url)).rejects.toThrow('HTTP 401');
    await expect(connectViewer(`${server.url}/?token=wrong-token-of-length`)).rejects.toThrow(
      'HTTP 401',
    );
    const viewer = await viewerOf(`${server.url}/?token=${token}`, {
      Origin: 'https://anywhere.example',
    });
    expect(viewer.channels.length).toBeGreaterThan(0);
  });
});

describe('a slow viewer', () => {
  it('loses messages, counted by topic, while a fast one beside it gets them all', async () => {
    server = await serveFoxglove(hal, { port: 0 });
    const fast = await viewerOf(server.url);
    const slow = await viewerOf(server.url);
    await fast.subscribe('/hal/log');
    await slow.subscribe('/hal/log');
    // the slow viewer stops reading, as one on a stalled link: the kernel's buffers fill, then
    // the server's queue for it
    pauseReading(slow);
    const live = server;
    const line = 'x'.repeat(32 * 1024);
    let sent = 0;
    while (live.stats().dropped === 0 && sent < 40_000) {
      for (let i = 0; i < 50; i++) {
        // a log call answers at once, whoever watches
        expect(live.hal.communication.log(`${sent++} ${line}`, 'info')).toBeUndefined();
      }
      await fast.until(() => robotLines(fast).length >= sent);
    }
    const stats = live.stats();
    expect(stats.dropped).toBeGreaterThan(0);
    const lossy = stats.drops.filter((d) => d.dropped > 0);
    expect(lossy).toHaveLength(1);
    expect(lossy[0]!.byTopic).toEqual({ '/hal/log': lossy[0]!.dropped });
    // the fast viewer got every line, in order, and the server's word on the slow one
    const got = robotLines(fast).map((m) => Number(String(m.value['message']).split(' ')[0]));
    expect(got).toEqual([...Array(sent).keys()]);
    const said = fast.on('/hal/log').filter((m) => m.value['name'] === 'hal:foxglove');
    expect(said.map((m) => m.value['message'])).toContain(
      `${lossy[0]!.client} cannot keep up: dropping its messages on /hal/log (counted)`,
    );
  });
});

/** The log lines from the robot (not the server's own). */
function robotLines(viewer: Viewer) {
  return viewer.on('/hal/log').filter((m) => m.value['name'] === 'sim-1');
}

/** Stops reading the viewer's TCP socket (as a viewer on a stalled link would). */
function pauseReading(viewer: Viewer): void {
  // ws keeps its TCP socket in _socket: no public way to stall a reader
  const socket = viewer.socket as unknown as { _socket: { pause(): void } };
  socket._socket.pause();
}
