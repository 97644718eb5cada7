// `hal look` as a user runs it (docs/perception.md): the CLI from source as a process, the embedded
// simulator put in a world file of the eval task format. What it lists must be the world's objects
// the camera can see, where the file puts them; the annotated frame it saves must show them boxed.
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { LookDocumentSchema } from '@hal/cli';
import type { LookDocument } from '@hal/cli';
import jpeg from 'jpeg-js';
import { runHalProcess } from '../helpers/hal-process.js';
import type { HalRun } from '../helpers/hal-process.js';

/** Two objects ahead of the robot (a red box left, a blue pillar right) and one behind it. */
const WORLD = {
  map: 'empty',
  start: { x: -0.5, y: 0, yawDeg: 0 },
  objects: [
    { name: 'red-box', kind: 'box', colour: 'red', x: 0.5, y: 0.2 },
    { name: 'blue-pillar', kind: 'cylinder', colour: 'blue', x: 0.7, y: -0.45 },
    { name: 'green-box', kind: 'box', colour: 'green', x: -1.5, y: 0 },
  ],
};

let dir: string;
let worldFile: string;
let json: HalRun;
let document: LookDocument;

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-look-'));
  worldFile = join(dir, 'world.json');
  await writeFile(worldFile, JSON.stringify(WORLD));
  json = await runHalProcess(
    ['look', '--sim', '--world', worldFile, '--json', '--save', join(dir, 'look.jpg')],
    60_000,
  );
  expect(json.stderr).toBe('');
  expect(json.code).toBe(0);
  document = LookDocumentSchema.parse(JSON.parse(json.stdout));
}, 70_000);

afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

describe('hal look --sim --world FILE', () => {
  it('lists the objects of the world the camera sees, where the file puts them (within 10 cm)', () => {
    expect(document.objects.map((o) => o.label).sort()).toStrictEqual(['blue pillar', 'red box']);
    for (const object of WORLD.objects.slice(0, 2)) {
      const seen = document.objects.find((o) => o.colour === object.name.split('-')[0]);
      expect(seen, object.name).toBeDefined();
      const error = Math.hypot((seen?.world.xM ?? 0) - object.x, (seen?.world.yM ?? 0) - object.y);
      expect(error, `${object.name} at ${JSON.stringify(seen?.world)}`).toBeLessThan(0.1);
    }
    // the red box is to the left (bearing +), the pillar to the right, and both in front
    const red = document.objects.find((o) => o.colour === 'red');
    const blue = document.objects.find((o) => o.colour === 'blue');
    expect(red?.bearingDeg).toBeGreaterThan(0);
    expect(blue?.bearingDeg).toBeLessThan(0);
    expect(document.pose).toStrictEqual({ xM: -0.5, yM: 0, yawDeg: 0 });
  });

  it('gives the free floor per 5 degrees across the view, blocked where the objects stand', () => {
    const bearings = document.freeSpace.map((b) => b.bearingDeg);
    expect(bearings[0]).toBeGreaterThanOrEqual(25);
    expect(bearings.at(-1)).toBeLessThanOrEqual(-25);
    for (const bin of document.freeSpace) {
      expect(bin.toDeg - bin.fromDeg).toBe(5);
      expect(bin.freeM).toBeLessThanOrEqual(2.5);
    }
    const red = document.objects.find((o) => o.colour === 'red');
    const atRed = document.freeSpace.find(
      (b) => Math.abs(b.bearingDeg - (red?.bearingDeg ?? 0)) <= 2.5,
    );
    expect(atRed?.blocked).toBe(true);
    expect(atRed?.freeM).toBeGreaterThan((red?.nearDistanceM ?? 0) - 0.1);
    expect(atRed?.freeM).toBeLessThan((red?.nearDistanceM ?? 0) + 0.1);
  });

  it('saves a 320x240 JPEG with each object boxed in its colour', async () => {
    expect(document.saved).toBe(join(dir, 'look.jpg'));
    const image = jpeg.decode(await readFile(join(dir, 'look.jpg')), { useTArray: true });
    expect([image.width, image.height]).toStrictEqual([320, 240]);
    const red = document.objects.find((o) => o.colour === 'red');
    expect(red).toBeDefined();
    const { left, top, right, bottom } = red!.image;
    // the outer line of the box, just left of the object's pixels (the floor or the wall there
    // otherwise): red, the box's colour
    let r = 0;
    let g = 0;
    let n = 0;
    for (let y = Math.max(top, 12); y <= Math.min(bottom, 239); y += 1) {
      const o = (y * 320 + (left - 1)) * 4;
      r += image.data[o] ?? 0;
      g += image.data[o + 1] ?? 0;
      n += 1;
    }
    expect(n).toBeGreaterThan(10);
    expect(r / n, `column ${left - 1}, rows ${top}..${bottom}`).toBeGreaterThan(180);
    expect(g / n).toBeLessThan(110);
    expect(right).toBeGreaterThan(left);
  });

  it('names them in its text output, with bearing, distance and world position', async () => {
    const text = await runHalProcess(['look', '--sim', '--world', worldFile], 60_000);
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toMatch(/2 objects in view/);
    expect(text.stdout).toMatch(
      /red box +bearing +\+\d+\.\d° +distance \d\.\d\d m +at x 0\.[45]\d m, y 0\.[12]\d m/,
    );
    expect(text.stdout).toMatch(
      /blue pillar +bearing +-\d+\.\d° +distance \d\.\d\d m +at x 0\.[67]\d m, y -0\.4\d m/,
    );
    expect(text.stdout).not.toContain('green');
    expect(text.stdout).toMatch(/free floor per 5° of bearing/);
  }, 60_000);
});

describe('hal look refuses', () => {
  it('a world file that is no world: exit 2, naming the file and the field', async () => {
    const bad = join(dir, 'bad-world.json');
    await writeFile(bad, JSON.stringify({ map: 'empty', start: { x: 'west', y: 0 } }));
    const run = await runHalProcess(['look', '--sim', '--world', bad], 60_000);
    expect(run.code).toBe(2);
    expect(run.stderr).toContain(bad);
    expect(run.stderr).toMatch(/"start\.x" .*expected number/);
    expect(run.stdout).toBe('');
    const notJson = join(dir, 'not-json.json');
    await writeFile(notJson, '{ map: empty');
    const second = await runHalProcess(['look', '--sim', '--world', notJson, '--json'], 60_000);
    expect(second.code).toBe(2);
    expect(JSON.parse(second.stderr)).toMatchObject({
      error: { code: 'USAGE', message: expect.stringContaining(`${notJson}: not JSON`) },
    });
  }, 60_000);

  it('a robot without a camera, naming it', async () => {
    const blind = join(dir, 'blind.json');
    await writeFile(blind, JSON.stringify({ ...WORLD, sensors: { camera: false } }));
    const run = await runHalProcess(['look', '--sim', '--world', blind], 60_000);
    expect(run.code).toBe(1);
    expect(run.stderr).toMatch(
      /^hal: NOT_IMPLEMENTED: the simulator \(world .*blind\.json\) \(sim-robot-1\) has no camera/m,
    );
  }, 60_000);

  it('--world without --sim, and a --save file that exists, before touching a robot', async () => {
    const run = await runHalProcess(['look', '--udp', '127.0.0.1:9', '--world', worldFile], 60_000);
    expect(run.code).toBe(2);
    expect(run.stderr).toContain('"--world" needs --sim');
    const again = await runHalProcess(['look', '--sim', '--save', join(dir, 'look.jpg')], 60_000);
    expect(again.code).toBe(2);
    expect(again.stderr).toMatch(/"--save" .*look\.jpg: exists \(give --overwrite to replace it\)/);
  }, 60_000);
});
