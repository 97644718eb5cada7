// `hal serve --sim --foxglove 0` as a user runs it: a real process, a Foxglove viewer (the
// `@foxglove/ws-protocol` client) that sees the robot's pose and e-stops it, and the options'
// refusals before any robot is touched.
import { afterAll, describe, expect, it } from 'vitest';
import { runHal } from '@hal/cli';
import { captureIO } from '../cli/capture-io.js';
import { startHalProcess, stopAllHal } from '../helpers/hal-process.js';
import { connectViewer } from './viewer.js';

interface ServeEvent {
  event: string;
  foxglove?: { url: string };
  ws?: { url: string };
}

afterAll(stopAllHal);

describe('hal serve --foxglove', () => {
  it('serves the simulator to a Foxglove viewer, which sees the pose and e-stops it', async () => {
    const hal = startHalProcess<ServeEvent>(['--json', 'serve', '--sim', '--foxglove', '0']);
    try {
      const serving = await hal.waitFor((e) => e.event === 'serving');
      const url = serving.foxglove!.url;
      expect(url).toMatch(/^ws:\/\/127\.0\.0\.1:\d+$/);
      expect(serving.ws).toBeUndefined();
      const viewer = await connectViewer(url);
      try {
        await viewer.subscribe('/hal/pose', '/hal/safety');
        await viewer.until(() => viewer.on('/hal/pose').length >= 3);
        expect(viewer.on('/hal/pose')[0]!.value).toMatchObject({ frame_id: 'world' });
        const answer = await viewer.call('/hal/emergency_stop', { reason: 'test' });
        expect(answer).toEqual({ success: true, emergency_stopped: true });
        await viewer.until(() => viewer.on('/hal/safety').length >= 1);
        expect(viewer.on('/hal/safety')[0]!.value).toMatchObject({
          event: 'emergency_stop',
          reason: 'test',
        });
      } finally {
        viewer.close();
      }
      expect(await hal.stop()).toBe(0);
    } finally {
      await hal.stop('SIGKILL');
    }
  });

  it('serves the live view beside WebSocket, each on its own port', async () => {
    const hal = startHalProcess<ServeEvent>([
      '--json',
      'serve',
      '--sim',
      '--ws-port',
      '0',
      '--foxglove',
      '0',
    ]);
    try {
      const serving = await hal.waitFor((e) => e.event === 'serving');
      expect(serving.ws!.url).toMatch(/^ws:\/\//);
      expect(serving.foxglove!.url).toMatch(/^ws:\/\//);
      expect(serving.foxglove!.url).not.toBe(serving.ws!.url);
      const viewer = await connectViewer(serving.foxglove!.url);
      expect(viewer.info.name).toMatch(/^hal /);
      viewer.close();
    } finally {
      await hal.stop();
    }
  });

  it('refuses a non-loopback live view without a token, --foxglove-* without --foxglove, --host without --ws-port', async () => {
    // usage errors, before any robot is opened: the command as the launcher runs it, in-process
    const refusal = async (args: string[]) => {
      const io = captureIO();
      return { code: await runHal(args, io), stderr: io.stderr() };
    };
    const open = await refusal(['serve', '--sim', '--foxglove', '0', '--foxglove-host', '0.0.0.0']);
    expect(open.code).toBe(2);
    expect(open.stderr).toMatch(/needs a token.*--foxglove-token/);
    const stray = await refusal(['serve', '--sim', '--ws-port', '0', '--foxglove-token', 'x']);
    expect(stray.code).toBe(2);
    expect(stray.stderr).toMatch(/"--foxglove-token" needs --foxglove/);
    // beside --foxglove alone, the WebSocket options still want --ws-port
    const host = await refusal(['serve', '--sim', '--foxglove', '0', '--host', '127.0.0.1']);
    expect(host.code).toBe(2);
    expect(host.stderr).toMatch(/"--host" needs --ws-port/);
    const nowhere = await refusal(['serve', '--sim']);
    expect(nowhere.code).toBe(2);
    expect(nowhere.stderr).toMatch(/--foxglove \[port\] for a live view/);
  });
});
