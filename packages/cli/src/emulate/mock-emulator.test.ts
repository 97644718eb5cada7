// The mock robot `hal emulate` serves where there is no cube-emulator: its ready line, the TXT
// record it announces, and PhysicalHAL driving it over real UDP on 127.0.0.1.
import { parseAnnouncementTxt } from '@hal/discovery';
import { PhysicalHAL } from '@hal/physical';
import { afterEach, describe, expect, it } from 'vitest';
import type { EmulateCliOptions } from './emulate-options.js';
import type { EmulatorProcess } from './emulator-process.js';
import { startMockEmulator } from './mock-emulator.js';

const options = (more: Partial<EmulateCliOptions> = {}): EmulateCliOptions => ({
  udpPort: 0,
  bind: '127.0.0.1',
  deviceId: 'cube-mock-test',
  insecure: false,
  pty: true,
  announce: false,
  ...more,
});

describe('startMockEmulator', () => {
  const started: EmulatorProcess[] = [];
  afterEach(async () => {
    for (const emulator of started.splice(0)) await emulator.stop();
  });

  it("prints cube-emulator's ready line (no pty) and announces the robot's own hello", async () => {
    const emulator = await startMockEmulator(options({ key: 'c0ffee', timeScale: 20 }));
    started.push(emulator);
    const { ready } = emulator;
    expect(ready).toMatchObject({
      event: 'ready',
      pty: '',
      device_id: 'cube-mock-test',
      auth: 'hmac-sha256',
      protocol_version: '1.1',
    });
    expect(ready.udp_port).toBeGreaterThan(0);
    const parsed = parseAnnouncementTxt(ready.mdns!.txt);
    expect(parsed).toMatchObject({
      ok: true,
      announcement: { deviceId: 'cube-mock-test', auth: 'hmac-sha256', protocolVersion: '1.1' },
    });
    if (parsed.ok) expect(parsed.announcement.capabilities).toContain('safety.estop:v1.0');

    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: ready.udp_port, key: 'c0ffee' },
      },
      { timeScale: 20 },
    );
    try {
      await hal.initialize();
      expect(hal.identity?.deviceId).toBe('cube-mock-test');
      expect((await hal.locomotion.moveForward(3)).success).toBe(true);
    } finally {
      await hal.cleanup();
    }
  });

  it('refuses a non-loopback address without a key, as cube-emulator does', async () => {
    await expect(startMockEmulator(options({ bind: '0.0.0.0' }))).rejects.toMatchObject({
      code: 'FAILED',
      message: expect.stringContaining('--key'),
    });
  });

  it('names the port in use and the option that changes it', async () => {
    const first = await startMockEmulator(options());
    started.push(first);
    const port = first.ready.udp_port;
    await expect(startMockEmulator(options({ udpPort: port }))).rejects.toMatchObject({
      code: 'FAILED',
      message: `port ${port} is in use (EADDRINUSE); choose another with --udp-port`,
    });
  });
});
