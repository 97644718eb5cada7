// What the calibration tests against the emulated robot share: a calibration directory of
// their own per test, the emulator at a fast clock, and the robot's own word for its steps.
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PhysicalHAL } from '@hal/physical';
import type { PhysicalHALOptions } from '@hal/physical';
import { afterAll, afterEach, beforeEach } from 'vitest';
import { LONGEST_HOST_TIMEOUT_MS, startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator, EmulatorEvent } from '../physical/emulator.js';

export const TIME_SCALE = 10;
export const DEVICE = 'cube-calib';

/** The steps the firmware makes for `cm` on wheels of `diameterCm` (4096 a turn; it truncates). */
export const stepsFor = (cm: number, diameterCm: number) =>
  Math.trunc((cm * 4096) / (Math.PI * diameterCm));

/** A fresh calibration directory per test (and `$HAL_CALIBRATION_DIR` naming it); emulators stopped after. */
export function calibrationDirPerTest(): { dir: () => string; env: () => Record<string, string> } {
  let dir = '';
  beforeEach(async () => {
    dir = await mkdtemp(join(tmpdir(), 'hal-calibrate-'));
  });
  afterEach(async () => {
    await stopAllEmulators();
    await rm(dir, { recursive: true, force: true });
  });
  afterAll(stopAllEmulators);
  return { dir: () => dir, env: () => ({ HAL_CALIBRATION_DIR: dir }) };
}

export const emulated = (udpPort?: number) =>
  startEmulator({
    timeScale: TIME_SCALE,
    // 1 s of real time at TIME_SCALE: the default's 200 ms was outlasted by a heartbeat held back
    // on a loaded machine, stopping a calibration run
    hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS,
    deviceId: DEVICE,
    pty: false,
    ...(udpPort === undefined ? {} : { udpPort }),
  });

/** The `hal` options that name `e` over UDP. */
export const udpOf = (e: Emulator) => [
  '--udp',
  `127.0.0.1:${e.udpPort}`,
  '--time-scale',
  String(TIME_SCALE),
];

/** The motions `e` started since its event number `from`. */
export const movesSince = (e: Emulator, from: number): EmulatorEvent[] =>
  e.events.slice(from).filter((event) => event.event === 'move_started');

/** A PhysicalHAL on `e` over UDP (not yet initialised). */
export function halOn(e: Emulator, options: PhysicalHALOptions = {}): PhysicalHAL {
  return new PhysicalHAL(
    {
      mode: 'physical',
      deviceId: DEVICE,
      connection: { type: 'wifi', host: '127.0.0.1', udpPort: e.udpPort },
    },
    { timeScale: TIME_SCALE, ...options },
  );
}
