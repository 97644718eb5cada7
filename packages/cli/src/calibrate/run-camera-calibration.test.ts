// The camera calibration's procedure with two distances: the person is asked to move the target
// between them (here the simulated robot backs away instead, which is the same to the camera),
// and the lens height is fitted with the tilt.
import { SimulationHAL, World } from '@hal/simulation';
import { V1_CAMERA } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import type { Prompter } from './prompt.js';
import { runCameraCalibration } from './run-camera-calibration.js';

let hal: SimulationHAL | undefined;
afterEach(async () => {
  await hal?.cleanup();
  hal = undefined;
});

async function redBoxAhead(nearM: number, camera: { tiltDeg: number; heightM: number }) {
  const world = new World({
    map: {
      name: 'target',
      obstacles: [
        {
          kind: 'box',
          x: nearM + 0.1,
          y: 0,
          width: 0.2,
          depth: 0.2,
          height: 0.2,
          color: '#d62828',
        },
      ],
    },
  });
  hal = new SimulationHAL({ world, camera });
  await hal.initialize();
  return hal;
}

describe('runCameraCalibration', () => {
  it('asks before each distance and fits tilt and lens height from two', async () => {
    const sim = await redBoxAhead(0.35, { tiltDeg: 22, heightM: 0.11 });
    const asked: string[] = [];
    const prompter: Prompter = {
      line: async (question) => {
        asked.push(question);
        // the second placement: 45 cm farther
        if (asked.length === 2) await sim.locomotion.moveBackward(45);
        return '';
      },
      positive: () => Promise.reject(new Error('not asked')),
      close: () => undefined,
    };
    const io = captureIO();
    const run = await runCameraCalibration(
      sim,
      V1_CAMERA,
      { distancesM: [0.35, 0.8], colour: 'red', frames: 2, prompter },
      io,
      { json: false },
    );
    expect(asked).toHaveLength(2);
    expect(io.stderr()).toContain(
      "1/2 place the red target straight ahead, its near face 35.0 cm from the robot's centre.",
    );
    expect(io.stderr()).toContain('2/2 place the red target straight ahead, its near face 80.0 cm');
    expect(run.fittedHeight).toBe(true);
    expect(Math.abs(run.after.tiltDeg - 22)).toBeLessThan(1);
    expect(Math.abs(run.after.heightM - 0.11)).toBeLessThan(0.01);
    expect(run.sightings.map((s) => s.distanceM)).toEqual([0.35, 0.8]);
    expect(run.residualM).toBeLessThan(0.01);
  });

  it('keeps a given lens height and fits the tilt alone', async () => {
    const sim = await redBoxAhead(0.5, { tiltDeg: 18, heightM: 0.12 });
    const run = await runCameraCalibration(
      sim,
      V1_CAMERA,
      { distancesM: [0.5], colour: 'red', frames: 2, heightM: 0.12 },
      captureIO(),
      { json: true },
    );
    expect(run.fittedHeight).toBe(false);
    expect(run.after.heightM).toBe(0.12);
    expect(Math.abs(run.after.tiltDeg - 18)).toBeLessThan(0.5);
    // with the wrong (V1) height instead, the tilt comes out wrong: the height matters
    const wrong = await runCameraCalibration(
      sim,
      V1_CAMERA,
      { distancesM: [0.5], colour: 'red', frames: 2 },
      captureIO(),
      { json: true },
    );
    expect(Math.abs(wrong.after.tiltDeg - 18)).toBeGreaterThan(1.5);
  });
});
