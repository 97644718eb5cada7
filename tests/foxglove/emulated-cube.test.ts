// The live view of a physical robot: the emulated cube (cube-emulator) over UDP through
// PhysicalHAL. Beside the pose, a viewer gets what only a physical robot reports: its wheel
// steps and its link's statistics, in the recorder's schemas.
import { serveFoxglove } from '@hal/foxglove';
import type { FoxgloveLiveServer } from '@hal/foxglove';
import { PhysicalHAL } from '@hal/physical';
import { afterAll, describe, expect, it } from 'vitest';
import { LONGEST_HOST_TIMEOUT_MS, startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { connectViewer } from './viewer.js';

afterAll(stopAllEmulators);

describe('the live view of the emulated cube', () => {
  it("sends the cube's reported wheel steps and its link's statistics as it drives", async () => {
    const emulator = await startEmulator({
      pty: false,
      timeScale: 8,
      hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS,
    });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-live',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: 8 },
    );
    let live: FoxgloveLiveServer | undefined;
    try {
      await hal.initialize();
      live = await serveFoxglove(hal, { port: 0, linkRateHz: 10 });
      const viewer = await connectViewer(live.url);
      try {
        const schemas = Object.fromEntries(viewer.channels.map((c) => [c.topic, c.schemaName]));
        expect(schemas).toMatchObject({
          '/hal/steps': 'hal.WheelSteps',
          '/hal/link': 'hal.LinkStats',
        });
        await viewer.subscribe('/hal/steps', '/hal/link', '/hal/pose');
        expect((await live.hal.locomotion.moveForward(5)).success).toBe(true);
        await viewer.until(
          () =>
            viewer.on('/hal/link').length >= 2 &&
            viewer.on('/hal/steps').some((m) => Number(m.value['left_steps']) > 0),
        );
        expect(viewer.on('/hal/link').at(-1)!.value).toMatchObject({ link_state: 'connected' });
        expect(Number(viewer.on('/hal/link').at(-1)!.value['received'])).toBeGreaterThan(0);
        const poses = viewer.on('/hal/pose');
        expect(poses.length).toBeGreaterThan(0);
      } finally {
        viewer.close();
      }
    } finally {
      await live?.close();
      await hal.cleanup();
      await emulator.stop();
    }
  });
});
