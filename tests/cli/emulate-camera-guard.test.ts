// The guard over the real wire (docs/tools.md, "The guard"): `hal emulate --camera` as a process
// runs the cube-emulator and serves the ESP32-CAM's interface with frames rendered from the
// emulated body's true pose in a world file; this process drives the cube with a guarded
// PhysicalHAL over UDP and the guard sees over MJPEG. The cube has no range sensors: the camera
// alone must stop it before the world's wall (the emulator itself would drive through it).
import { guardHal } from '@hal/perception';
import type { GuardedHAL } from '@hal/perception';
import type { PhysicalHAL } from '@hal/physical';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulatedCube } from '../helpers/emulated-cube.js';
import type { EmulatedCube } from '../helpers/emulated-cube.js';

const BODY_RADIUS_M = 0.07;
/** The wall's face, metres along x: 0.5 m ahead of the body's front at the start. */
const WALL_FACE_X = BODY_RADIUS_M + 0.5;
const WORLD = {
  map: {
    name: 'wall',
    arena: { width: 5, height: 5 },
    walls: [{ from: [WALL_FACE_X + 0.025, -1], to: [WALL_FACE_X + 0.025, 1], thickness: 0.05 }],
  },
  start: { x: 0, y: 0, yawDeg: 0 },
  objects: [],
};

let emulated: EmulatedCube;
let cube: PhysicalHAL;
let guarded: GuardedHAL;

beforeAll(async () => {
  emulated = await startEmulatedCube({ world: WORLD, timeScale: 2 });
  cube = emulated.physicalHal();
  guarded = guardHal(cube);
  await guarded.initialize();
}, 60_000);

afterAll(async () => {
  await guarded?.cleanup();
  await emulated?.dispose();
});

describe('the guard on hal emulate --camera, over UDP and MJPEG', { timeout: 90_000 }, () => {
  it('sees with the camera and stops the cube before the wall of the world file', async () => {
    expect(await guarded.senses()).toBe('camera');
    const result = await guarded.locomotion.moveForward(100);
    expect(result.code).toBe('OBSTACLE_AHEAD');
    expect(result.details).toMatchObject({ source: 'camera', when: 'during' });
    // the emulated body goes where its steps take it: its pose is the truth the frames show
    const pose = await cube.locomotion.getPose();
    const gap = WALL_FACE_X - (pose.position.x + BODY_RADIUS_M);
    expect(gap).toBeGreaterThan(0.05);
    expect(gap).toBeLessThan(0.15);
    expect(Math.abs((result.details?.['distanceM'] as number) - gap)).toBeLessThan(0.03);
    // and a motion starting there is refused at once: nothing moves
    const again = await guarded.locomotion.moveForward(20);
    expect(again.code).toBe('OBSTACLE_AHEAD');
    expect(again.details).toMatchObject({ when: 'before', travelledM: 0 });
    expect((await cube.locomotion.getPose()).position.x).toBeCloseTo(pose.position.x, 4);
  });
});
