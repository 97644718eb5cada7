// The browser demo's Remote robot card in Chromium: `hal serve --ws-port` serves PhysicalHAL
// to the emulated robot with a token; the page connects with the URL and token fields, drives it
// through a HybridHAL whose twin is the page's simulated robot, and shows their divergence.
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startServe, stopAllServes } from '../remote/serve-command.js';
import { openDemoInChromium } from './demo-browser.js';
import type { DemoBrowser } from './demo-browser.js';

interface RemoteState {
  connection: string;
  role: string;
  pose: { x: number; y: number; yaw: number } | null;
  divergence: { positionM: number; yawRad: number; exceeded: boolean } | null;
  lastResult: { call: string; success: boolean; code?: string } | null;
}
type Hooked = { simDemo?: { remote(): RemoteState } };

describe('apps/sim-demo Remote robot card in Chromium', () => {
  let demo: DemoBrowser;
  let page: Page;

  beforeAll(async () => {
    demo = await openDemoInChromium('remote-demo', { width: 1400, height: 1000 });
    page = demo.page;
  }, 90_000);

  afterAll(async () => {
    await demo?.close();
    stopAllServes();
    await stopAllEmulators();
  }, 30_000);

  const remoteState = () => page.evaluate(() => (window as unknown as Hooked).simDemo?.remote());
  /**
   * Waits for `holds(arg)` to be true in the page (up to 15 s: a loaded machine slows every hop
   * from the page to the emulated robot); a timeout says what the card and the log showed.
   */
  const eventually = async (
    what: string,
    holds: (arg: string | undefined) => boolean,
    arg?: string,
  ) => {
    try {
      await page.waitForFunction(holds, arg, { timeout: 15_000 });
    } catch (error) {
      const log = await page.locator('#log').innerText();
      throw new Error(`${what} never came: ${JSON.stringify(await remoteState())}; log:\n${log}`, {
        cause: error,
      });
    }
  };
  /** Waits for the card's connection to be `wanted`. */
  const connection = (wanted: RemoteState['connection']) =>
    eventually(
      `the card's "${wanted}"`,
      (w) => (window as unknown as Hooked).simDemo?.remote().connection === w,
      wanted,
    );

  it('connects with URL and token, moves the emulated robot and its twin, and shows the divergence', async () => {
    const token = 'browser-demo-token-123';
    const emulator = await startEmulator({ pty: false, hostTimeoutMs: 10_000 });
    const wsUrl = await startServe(
      // the page's heartbeats come from Chromium's timers, which a loaded machine can hold up
      // past the default 2 s; the silent-controller stop is tested in tests/remote
      [
        '--udp',
        `127.0.0.1:${emulator.udpPort}`,
        '--device',
        'cube-remote',
        '--heartbeat-timeout',
        '10000',
      ],
      {
        HAL_SERVE_TOKEN: token,
      },
    );
    await page.goto(`${demo.url}?map=empty`, { waitUntil: 'load', timeout: 20_000 });
    await page.waitForFunction(
      () => (window as unknown as Hooked).simDemo !== undefined,
      undefined,
      {
        timeout: 15_000,
      },
    );

    // A wrong token is refused and said so.
    await page.locator('#remote-url').fill(wsUrl);
    await page.locator('#remote-token').fill('not-the-right-token');
    await page.locator('#remote-connect').click();
    await connection('failed');

    await page.locator('#remote-token').fill(token);
    await page.locator('#remote-connect').click();
    await connection('connected');
    expect((await remoteState())?.role).toBe('controller');
    // the card draws its badge once it has read the robot's pose, after its state changed
    await expect
      .poll(() => page.locator('#remote-badge').textContent(), { timeout: 5000 })
      .toBe('CONNECTED');

    await page.locator('[data-remote="forward"]').click();
    await page.waitForFunction(
      () => (window as unknown as Hooked).simDemo?.remote().lastResult?.call === 'forward',
      undefined,
      { timeout: 30_000 },
    );
    await eventually(
      'the moved pose',
      () => ((window as unknown as Hooked).simDemo?.remote().pose?.x ?? 0) > 0.09,
    );
    const state = await remoteState();
    expect(state?.lastResult).toEqual({ call: 'forward', success: true });
    expect(state?.pose?.x).toBeCloseTo(0.1, 2);
    expect(state?.divergence).toMatchObject({ exceeded: false });
    expect(state?.divergence?.positionM).toBeLessThan(0.005);
    // the card shows it once the refresh that follows the call has drawn it (after a getPose)
    await eventually('the divergence on the card', () =>
      /Twin divergence\d/.test(document.querySelector('#remote-info')?.textContent ?? ''),
    );
    expect(await emulator.waitForCount((e) => e.event === 'move_finished', 1)).toHaveLength(1);

    // The e-stop button latches the remote robot; the badge says so.
    await page.locator('[data-remote="estop"]').click();
    await eventually(
      'the E-STOP badge',
      () => document.getElementById('remote-badge')?.textContent === 'E-STOP',
    );
    // The only console error is the browser's own report of the refused wrong token.
    expect(demo.problems.filter((p) => !p.includes('not-the-right-token'))).toEqual([]);
  }, 150_000);
});
