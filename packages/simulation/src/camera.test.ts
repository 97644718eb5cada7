import jpeg from 'jpeg-js';
import { cameraProjection, horizonRow, pixelOfPoint } from '@hal/kinematics';
import { V1_CAMERA } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { renderRobotView } from './camera.js';
import { defaultJpegEncoder, encodeJpeg, jpegDataUrl } from './jpeg.js';
import { jpegJsEncoder, loadSharpEncoder } from './jpeg-encoders.js';
import type { JpegEncoder } from './jpeg-encoders.js';
import { World } from './world.js';

async function frameOf(world: World, robotId: string, encoder?: JpegEncoder) {
  const url = jpegDataUrl(
    await encodeJpeg(renderRobotView(world, world.robot(robotId)), 85, encoder),
  );
  expect(url.startsWith('data:image/jpeg;base64,')).toBe(true);
  const bytes = Buffer.from(url.slice('data:image/jpeg;base64,'.length), 'base64');
  return jpeg.decode(bytes, { useTArray: true });
}

const sharp = await loadSharpEncoder();
if (sharp === undefined) throw new Error('sharp (an optional dependency) is not installed');

function pixel(image: { width: number; data: Uint8Array }, x: number, y: number) {
  const i = (y * image.width + x) * 4;
  return { r: image.data[i] ?? 0, g: image.data[i + 1] ?? 0, b: image.data[i + 2] ?? 0 };
}

describe('renderRobotView', () => {
  it('renders a 320x240 JPEG with sky above the horizon and floor below', async () => {
    // An arena too large for its walls to be drawn (beyond the 15 m drawing distance).
    const world = new World({ map: { name: 'open', arena: { width: 40, height: 40 } } });
    world.addRobot({ id: 'r' });
    const image = await frameOf(world, 'r');
    expect([image.width, image.height]).toEqual([320, 240]);
    const sky = pixel(image, 160, 10);
    expect(sky.b).toBeGreaterThan(sky.r + 40);
    const floor = pixel(image, 160, 230);
    expect(Math.abs(floor.r - floor.b)).toBeLessThan(40);
    expect(floor.r).toBeGreaterThan(150);
  });

  const encoders: Array<[string, JpegEncoder]> = [
    ['jpeg-js', jpegJsEncoder],
    ['sharp', sharp],
  ];
  it.each(encoders)(
    'shows an obstacle in front in its colour, and not when the robot looks away (%s)',
    async (_name, encoder) => {
      // A red box 0.5 m ahead, nothing behind.
      const world = new World({
        map: {
          name: 'red box',
          obstacles: [
            { kind: 'box', x: 0.6, y: 0, width: 0.2, depth: 0.4, height: 0.3, color: '#ff0000' },
          ],
        },
      });
      const robot = world.addRobot({ id: 'r' });
      const ahead = await frameOf(world, 'r', encoder);
      // The box's near face spans the rows above where its base meets the floor, 0.45 m ahead
      // of the lens.
      const base = pixelOfPoint(cameraProjection(V1_CAMERA), { x: 0.5, y: 0, z: 0 });
      expect(base).toBeDefined();
      const centre = pixel(ahead, 160, Math.floor((base?.v ?? 0) - 10));
      expect(centre.r).toBeGreaterThan(150);
      expect(centre.g).toBeLessThan(80);
      expect(centre.b).toBeLessThan(80);

      robot.rotateDeg(180);
      world.advanceUntil(() => !robot.running, 10_000_000);
      const away = await frameOf(world, 'r', encoder);
      let red = 0;
      for (let y = 0; y < 240; y += 4) {
        for (let x = 0; x < 320; x += 4) {
          const p = pixel(away, x, y);
          if (p.r > 150 && p.g < 80 && p.b < 80) red += 1;
        }
      }
      expect(red).toBe(0);
    },
  );

  it('encodes with sharp in Node by default, and refuses a quality outside 1..100', async () => {
    expect(await defaultJpegEncoder()).toBe(sharp);
    const world = new World({ map: 'room' });
    const image = renderRobotView(world, world.addRobot());
    await expect(encodeJpeg(image, 0)).rejects.toThrow(/quality/);
    await expect(encodeJpeg(image, Number.NaN)).rejects.toThrow(/quality/);
  });

  it('draws a nearer obstacle larger than a farther one', () => {
    const world = new World({
      map: {
        name: 'post',
        obstacles: [{ kind: 'cylinder', x: 1, y: 0, radius: 0.1, color: '#00ff00' }],
      },
    });
    world.addRobot({ id: 'near', start: { x: 0.5, y: 0.8, yaw: 0 } });
    world.addRobot({ id: 'far', start: { x: -1.5, y: -0.8, yaw: 0 } });
    const greenColumns = (id: string) => {
      const robot = world.robot(id);
      const image = renderRobotView(world, robot, {});
      // Just below the horizon: level with the lens, where the post is at any distance.
      const row = Math.ceil(horizonRow(cameraProjection(V1_CAMERA))) + 1;
      let count = 0;
      for (let x = 0; x < image.width; x += 1) {
        const i = (row * image.width + x) * 4;
        if ((image.data[i + 1] ?? 0) > 150 && (image.data[i] ?? 0) < 100) count += 1;
      }
      return count;
    };
    // Point both robots at the post.
    for (const id of ['near', 'far']) {
      const robot = world.robot(id);
      const turn = (Math.atan2(0 - robot.y, 1 - robot.x) * 180) / Math.PI;
      robot.rotateDeg(turn);
      world.advanceUntil(() => !robot.running, 10_000_000);
    }
    expect(greenColumns('near')).toBeGreaterThan(greenColumns('far'));
    expect(greenColumns('far')).toBeGreaterThan(0);
  });
});
