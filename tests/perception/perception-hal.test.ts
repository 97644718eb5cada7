// Perception bound to a SimulationHAL: looks through captureFrame and getPose only, remembers
// what it saw across poses, and maps the free space it sees into the navigation grid.
import { OccupancyGrid } from '@hal/navigation';
import { ObjectMemory, Perception } from '@hal/perception';
import { SimulationHAL, World } from '@hal/simulation';
import { afterEach, describe, expect, it } from 'vitest';

let hal: SimulationHAL | undefined;
afterEach(async () => {
  await hal?.cleanup();
  hal = undefined;
});

async function simulation(world: World): Promise<SimulationHAL> {
  hal = new SimulationHAL({ world });
  await hal.initialize();
  return hal;
}

describe('Perception over a HAL', () => {
  it('remembers one object seen from two poses as one, where it is', async () => {
    const world = new World({
      map: {
        name: 'box',
        obstacles: [
          { kind: 'box', x: 1.2, y: 0.3, width: 0.3, depth: 0.3, height: 0.3, color: '#d62828' },
        ],
      },
    });
    const sim = await simulation(world);
    const perception = new Perception(sim);
    const first = await perception.look();
    expect(first.objects.map((o) => o.label)).toEqual(['red box']);
    await sim.locomotion.moveForward(30);
    const second = await perception.look();
    expect(second.remembered[0]?.id).toBe('red box 1');
    const [red] = perception.where('the red box');
    expect(red?.timesSeen).toBe(2);
    expect(Math.hypot((red?.x ?? 0) - 1.2, (red?.y ?? 0) - 0.3)).toBeLessThan(0.1);
    expect(perception.where('green')).toEqual([]);
    perception.memory.clear();
    expect(perception.where()).toEqual([]);
  });

  it('maps a wall it sees: occupied where the wall is, free before it, unknown behind', async () => {
    const world = new World({
      map: { name: 'wall', walls: [{ from: [1, -1], to: [1, 1], thickness: 0.05 }] },
    });
    const sim = await simulation(world);
    const grid = new OccupancyGrid({ widthM: 5, heightM: 5, resolutionM: 0.05 });
    const perception = new Perception(sim, { grid });
    await perception.look();
    await perception.look();
    expect(grid.stateAt(0.6, 0)).toBe('free');
    expect(grid.stateAt(0.98, 0)).toBe('occupied');
    expect(grid.stateAt(1.5, 0)).toBe('unknown');
    // Behind the robot: never in view.
    expect(grid.stateAt(-0.6, 0)).toBe('unknown');
  });

  it('says which call failed and how long it waited, when the camera never answers', async () => {
    const sim = await simulation(new World());
    sim.vision.captureFrame = () => new Promise<string>(() => undefined);
    const perception = new Perception(sim, { timeoutMs: 100 });
    await expect(perception.look()).rejects.toThrow('captureFrame gave no frame within 100 ms');
  });
});

describe('ObjectMemory', () => {
  const sighting = (colour: 'red' | 'blue', x: number, kind: 'box' | 'pillar' = 'box') => ({
    colour,
    kind,
    label: `${colour} ${kind}`,
    bearingDeg: 0,
    distanceM: 1,
    nearDistanceM: 0.85,
    widthM: 0.3,
    heightM: 0.3,
    confidence: 0.9,
    robot: { x: 1, y: 0 },
    world: { x, y: 0 },
    image: { left: 0, top: 0, right: 10, bottom: 10 },
    partial: [],
    detector: 'colour',
  });

  it('keeps two objects of one colour apart beyond the merge radius, and numbers them', () => {
    const memory = new ObjectMemory({ mergeRadiusM: 0.3 });
    memory.remember([sighting('red', 1), sighting('red', 2)], 1);
    memory.remember([sighting('red', 1.1)], 2);
    expect(memory.find('red box').map((o) => [o.id, o.timesSeen])).toEqual([
      ['red box 1', 2],
      ['red box 2', 1],
    ]);
    expect(memory.find('red box 2').map((o) => o.id)).toEqual(['red box 2']);
    expect(memory.find('blue')).toEqual([]);
    // A pillar of the same colour at the same place is another object.
    memory.remember([sighting('red', 1, 'pillar')], 3);
    expect(memory.size).toBe(3);
  });

  it('refuses options that make no sense', () => {
    expect(() => new ObjectMemory({ mergeRadiusM: 0 })).toThrow(/mergeRadiusM/);
    expect(() => new ObjectMemory({ minConfidence: 2 })).toThrow(/minConfidence/);
  });
});
