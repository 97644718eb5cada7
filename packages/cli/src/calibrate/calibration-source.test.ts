import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';
import { writeCalibrationFile } from '@hal/physical';
import type { CalibrationFile } from '@hal/physical';

const FILE: CalibrationFile = {
  version: 1,
  deviceId: 'cube-7',
  wheelDiameterCm: 6.6,
  wheelBaseCm: 10.4,
  calibratedAt: '2026-12-01T20:00:00.000Z',
};

let dir: string;
beforeEach(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-calibration-source-'));
});
afterEach(async () => {
  await rm(dir, { recursive: true, force: true });
});

describe('--sim --calibration', () => {
  it("gives the simulated robot the file's wheels: 5 cm is 987 steps of a 6.6 cm wheel", async () => {
    const path = join(dir, 'sim.json');
    await writeCalibrationFile(path, { ...FILE, deviceId: 'sim-1' });
    const io = captureIO();
    const argv = ['--json', 'drive', 'forward', '0.05', '--sim', '--time-scale', '20'];
    expect(await runHal([...argv, '--calibration', path], io), io.stderr()).toBe(0);
    const doc = io.jsonLines()[0] as { result: { data: { leftSteps: number } } };
    expect(doc.result.data.leftSteps).toBe(Math.trunc((5 * 4096) / (Math.PI * 6.6)));
  });

  it('takes a device id for the file of that device in the calibration directory', async () => {
    await writeCalibrationFile(join(dir, 'cube-7.json'), FILE);
    const io = captureIO({ HAL_CALIBRATION_DIR: dir });
    const argv = ['--json', 'drive', 'forward', '0.05', '--sim', '--time-scale', '20'];
    expect(await runHal([...argv, '--calibration', 'cube-7'], io), io.stderr()).toBe(0);
    const doc = io.jsonLines()[0] as { result: { data: { leftSteps: number } } };
    expect(doc.result.data.leftSteps).toBe(Math.trunc((5 * 4096) / (Math.PI * 6.6)));
    const missing = captureIO({ HAL_CALIBRATION_DIR: dir });
    expect(await runHal([...argv, '--calibration', 'cube-8'], missing)).toBe(1);
    expect(missing.stderr()).toContain(
      `calibration file ${join(dir, 'cube-8.json')} does not exist`,
    );
  });

  it("reads the repository's example file, as docs/cli.md uses it", async () => {
    const example = fileURLToPath(
      new URL('../../../../examples/calibration/cube-example.json', import.meta.url),
    );
    const io = captureIO();
    const argv = ['--json', 'drive', 'forward', '0.05', '--sim', '--time-scale', '20'];
    expect(await runHal([...argv, '--calibration', example], io), io.stderr()).toBe(0);
    const doc = io.jsonLines()[0] as { result: { data: { leftSteps: number } } };
    expect(doc.result.data.leftSteps).toBe(Math.trunc((5 * 4096) / (Math.PI * 6.1203)));
  });

  it('fails naming the file when it is corrupt, before driving', async () => {
    const path = join(dir, 'sim.json');
    await writeFile(path, '{"version": 1,');
    const io = captureIO();
    expect(await runHal(['drive', 'forward', '0.05', '--sim', '--calibration', path], io)).toBe(1);
    expect(io.stderr()).toMatch(
      `hal: INVALID_PARAMETER: calibration file ${path} is not valid JSON`,
    );
  });

  it('is a usage error with a robot that is not simulated, on UDP or serial', async () => {
    const io = captureIO();
    const argv = ['status', '--ws', 'ws://127.0.0.1:9', '--calibration', 'x.json'];
    expect(await runHal(argv, io)).toBe(2);
    expect(io.stderr()).toMatch(/"--calibration" needs --sim, --udp or --serial/);
  });
});
