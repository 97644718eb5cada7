// Perception on the simulator's rendered JPEG frames: the renderer and perception share one
// camera model, so what the camera sees is placed where the world has it.
import { clearanceAhead, FramePerceiver } from '@hal/perception';
import { encodeJpeg, World } from '@hal/simulation';
import type { WorldMapInput } from '@hal/simulation';
import { renderRobotView } from '@hal/simulation';
import { describe, expect, it } from 'vitest';

const dataUrl = (bytes: Uint8Array): string =>
  `data:image/jpeg;base64,${Buffer.from(bytes).toString('base64')}`;

async function look(
  map: WorldMapInput,
  start: { x: number; y: number; yaw: number },
  perceiver = new FramePerceiver(),
) {
  const world = new World({ map });
  const robot = world.addRobot({ start });
  const frame = dataUrl(await encodeJpeg(renderRobotView(world, robot), 85));
  return perceiver.perceive(frame, start);
}

const box = (x: number, y: number, color: string) =>
  ({ kind: 'box', x, y, width: 0.3, depth: 0.3, height: 0.3, color }) as const;
const pillar = (x: number, y: number, color: string) =>
  ({ kind: 'cylinder', x, y, radius: 0.15, height: 0.3, color }) as const;

describe('objects in a rendered frame', () => {
  it('finds a red box and a blue pillar, their kinds, and their world positions', async () => {
    const start = { x: -0.5, y: 0.2, yaw: 0.3 };
    const percept = await look(
      { name: 'two', obstacles: [box(0.6, 0.7, '#d62828'), pillar(0.9, 0.25, '#1d4ed8')] },
      start,
    );
    const labels = percept.objects.map((o) => o.label).sort();
    expect(labels).toEqual(['blue pillar', 'red box']);
    const red = percept.objects.find((o) => o.colour === 'red');
    const blue = percept.objects.find((o) => o.colour === 'blue');
    expect(Math.hypot((red?.world.x ?? 0) - 0.6, (red?.world.y ?? 0) - 0.7)).toBeLessThan(0.05);
    // At 1.4 m a row of the image spans 8 cm of floor: the pillar's base is placed to about that.
    expect(Math.hypot((blue?.world.x ?? 0) - 0.9, (blue?.world.y ?? 0) - 0.25)).toBeLessThan(0.08);
    // Bearing and distance are from the robot's own frame: the red box is to the left.
    expect(red?.bearingDeg).toBeGreaterThan(0);
    expect(blue?.bearingDeg).toBeLessThan(0);
    expect(red?.distanceM).toBeCloseTo(Math.hypot(1.1, 0.5), 1);
  });

  it('places objects by the pose it is given: a pose off by 0.5 m puts them 0.5 m off', async () => {
    const world: WorldMapInput = { name: 'one', obstacles: [box(1, 0, '#2a9d3f')] };
    const truth = await look(world, { x: 0, y: 0, yaw: 0 });
    const believed = await look(world, { x: 0, y: 0, yaw: 0 }, new FramePerceiver());
    expect(truth.objects[0]?.world.x).toBeCloseTo(believed.objects[0]?.world.x ?? 0, 6);
    const shifted = await new FramePerceiver().perceive(
      dataUrl(
        await encodeJpeg(
          renderRobotView(new World({ map: world }), new World({ map: world }).addRobot()),
          85,
        ),
      ),
      { x: 0.5, y: 0, yaw: 0 },
    );
    expect(shifted.objects[0]?.world.x).toBeCloseTo((truth.objects[0]?.world.x ?? 0) + 0.5, 6);
  });

  it('names no object for grey walls, the floor or the sky', async () => {
    const percept = await look(
      { name: 'room', walls: [{ from: [1, -1], to: [1, 1] }] },
      {
        x: 0,
        y: 0,
        yaw: 0,
      },
    );
    expect(percept.objects).toEqual([]);
    // An arena too large for its walls to be drawn: floor and sky only.
    const open = await look(
      { name: 'open', arena: { width: 40, height: 40 } },
      { x: 0, y: 0, yaw: 0 },
    );
    expect(open.objects).toEqual([]);
  });
});

describe('free space in a rendered frame', () => {
  it('sees a wall 1 m ahead as the end of the free floor, and nothing in an open arena', async () => {
    const walled = await look(
      { name: 'wall', walls: [{ from: [1, -2], to: [1, 2], thickness: 0.04 }] },
      { x: 0, y: 0, yaw: 0 },
    );
    const ahead = clearanceAhead(walled.freeSpace, 0.07, 0.1);
    expect(ahead.blocked).toBe(true);
    // The wall's face is 0.98 m from the centre: 0.91 m from the body's front.
    expect(Math.abs(ahead.aheadM - 0.91)).toBeLessThan(0.05);

    const open = await look(
      { name: 'open', arena: { width: 12, height: 12 } },
      {
        x: 0,
        y: 0,
        yaw: 0,
      },
    );
    const clear = clearanceAhead(open.freeSpace, 0.07, 0.1);
    expect(clear.blocked).toBe(false);
    expect(open.freeSpace.every((c) => !c.hit)).toBe(true);
  });
});

describe('bad frames', () => {
  it('refuses what is not a JPEG and a frame of another size, with errors that say so', async () => {
    const perceiver = new FramePerceiver();
    await expect(
      perceiver.perceive('data:image/jpeg;base64,aGVsbG8=', { x: 0, y: 0, yaw: 0 }),
    ).rejects.toThrow(/not a JPEG/);
    await expect(perceiver.perceive('%%%', { x: 0, y: 0, yaw: 0 })).rejects.toThrow(/base64/);
    const world = new World();
    const small = renderRobotView(world, world.addRobot(), { width: 160, height: 120 });
    await expect(
      perceiver.perceive(dataUrl(await encodeJpeg(small, 85)), { x: 0, y: 0, yaw: 0 }),
    ).rejects.toThrow(/160x120 but the camera model says 320x240/);
  });
});
