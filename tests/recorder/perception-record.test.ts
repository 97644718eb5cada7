// What perception believed, recorded beside where the robot was: a few looks in the simulator,
// the MCAP read back, the perception topics there with Foxglove's schemas, the remembered objects
// where they are in the world, the grid's cells where the wall is.
import { OccupancyGrid } from '@hal/navigation';
import { Perception } from '@hal/perception';
import {
  McapRecorder,
  memorySink,
  OCCUPANCY,
  PERCEPTION_TOPICS,
  readRecording,
  recordHal,
  recordPerception,
} from '@hal/recorder';
import type { Recording } from '@hal/recorder';
import { SimulationHAL, World } from '@hal/simulation';
import { V1_CAMERA } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { expectWellFormed } from './well-formed.js';

interface Entity {
  id: string;
  frame_id: string;
  metadata: Array<{ key: string; value: string }>;
  cubes: Array<{ pose: { position: { x: number; y: number; z: number } } }>;
  cylinders: Array<{ pose: { position: { x: number; y: number; z: number } } }>;
  texts: Array<{ text: string }>;
}
interface SceneUpdate {
  deletions: Array<{ type: number }>;
  entities: Entity[];
}
interface Grid {
  frame_id: string;
  pose: { position: { x: number; y: number } };
  column_count: number;
  cell_size: { x: number; y: number };
  fields: Array<{ name: string; type: number }>;
  data: string;
}

const world = () =>
  new World({
    map: {
      name: 'two objects and a wall',
      walls: [{ from: [2, -1.5], to: [2, 1.5], thickness: 0.05 }],
      obstacles: [
        { kind: 'box', x: 1.0, y: 0.3, width: 0.2, depth: 0.2, height: 0.2, color: '#d62828' },
        { kind: 'cylinder', x: 1.3, y: -0.35, radius: 0.08, height: 0.3, color: '#2a9d3f' },
      ],
    },
  });

async function recordLooks(count: number, namespace?: string): Promise<Recording> {
  const sink = memorySink();
  const recorder = await McapRecorder.create(sink);
  const hal = recordHal(new SimulationHAL({ world: world() }), recorder, {
    posePeriodMs: 0,
    ...(namespace === undefined ? {} : { namespace }),
  });
  await hal.initialize();
  const grid = new OccupancyGrid({ widthM: 6, heightM: 6, resolutionM: 0.05 });
  const perception = new Perception(hal, { grid });
  const recording = recordPerception(recorder, perception, {
    gridPeriodMs: 0,
    ...(namespace === undefined ? {} : { namespace }),
  });
  for (let i = 0; i < count; i += 1) await perception.look();
  expect(recording.looks).toBe(count);
  recording.stop();
  await perception.look(); // not recorded
  await hal.cleanup();
  const stats = await recorder.close();
  expect(stats.dropped).toBe(0);
  const read = await readRecording(sink.bytes());
  expectWellFormed(read);
  return read;
}

const on = (recording: Recording, topic: string) =>
  recording.messages.filter((m) => m.topic === topic).map((m) => m.value);

describe('recordPerception', () => {
  it('writes the remembered objects, the sightings and the grid, in Foxglove schemas', async () => {
    const recording = await recordLooks(3);
    expect(recording.channels.get(PERCEPTION_TOPICS.objects)?.schemaName).toBe(
      'foxglove.SceneUpdate',
    );
    expect(recording.channels.get(PERCEPTION_TOPICS.detections)?.schemaName).toBe(
      'foxglove.SceneUpdate',
    );
    expect(recording.channels.get(PERCEPTION_TOPICS.grid)?.schemaName).toBe('foxglove.Grid');

    // the camera model perception projected with is in the robot's metadata
    expect(JSON.parse(recording.metadata.get('hal.robot')!['camera']!)).toEqual(V1_CAMERA);

    const scenes = on(recording, PERCEPTION_TOPICS.objects) as SceneUpdate[];
    expect(scenes).toHaveLength(3);
    const last = scenes.at(-1)!;
    expect(last.deletions).toEqual([expect.objectContaining({ type: 1 })]);
    const byId = new Map(last.entities.map((e) => [e.id, e]));
    expect([...byId.keys()].sort()).toEqual(['green pillar 1', 'red box 1']);
    const box = byId.get('red box 1')!;
    expect(box.frame_id).toBe('world');
    expect(box.cubes).toHaveLength(1);
    expect(box.cylinders).toHaveLength(0);
    const boxAt = box.cubes[0]!.pose.position;
    expect(Math.hypot(boxAt.x - 1.0, boxAt.y - 0.3)).toBeLessThan(0.1);
    expect(boxAt.z).toBeGreaterThan(0.05);
    expect(box.metadata).toContainEqual({ key: 'times_seen', value: '3' });
    expect(box.texts[0]?.text).toBe('red box 1');
    const pillar = byId.get('green pillar 1')!;
    expect(pillar.cylinders).toHaveLength(1);
    const pillarAt = pillar.cylinders[0]!.pose.position;
    expect(Math.hypot(pillarAt.x - 1.3, pillarAt.y + 0.35)).toBeLessThan(0.1);

    const sightings = on(recording, PERCEPTION_TOPICS.detections) as SceneUpdate[];
    expect(sightings).toHaveLength(3);
    expect(
      sightings[0]!.entities.map((e) => e.metadata.find((m) => m.key === 'label')?.value),
    ).toEqual(expect.arrayContaining(['red box', 'green pillar']));
  });

  it('writes the grid with its origin, resolution and one uint8 occupancy field: the wall occupied, the floor before it free', async () => {
    const recording = await recordLooks(2);
    const grids = on(recording, PERCEPTION_TOPICS.grid) as Grid[];
    expect(grids.length).toBeGreaterThanOrEqual(1);
    const grid = grids.at(-1)!;
    expect(grid.frame_id).toBe('world');
    expect(grid.pose.position).toMatchObject({ x: -3, y: -3 });
    expect(grid.column_count).toBe(120);
    expect(grid.cell_size).toEqual({ x: 0.05, y: 0.05 });
    expect(grid.fields).toEqual([{ name: 'occupancy', offset: 0, type: 1 }]);
    const cells = Buffer.from(grid.data, 'base64');
    expect(cells).toHaveLength(120 * 120);
    // along y = 0 (cell centres): free floor up to the wall at x = 1.975, occupied there
    const row = Math.floor(3 / 0.05);
    const along = (x: number) => cells[row * 120 + Math.floor((x + 3) / 0.05 + 1e-9)];
    const firstOccupied = [...Array(60).keys()]
      .map((i) => i * 0.05 + 0.025)
      .find((x) => along(x) === OCCUPANCY.occupied);
    expect(firstOccupied).toBeGreaterThan(1.85);
    expect(firstOccupied).toBeLessThan(2.05);
    expect(along(0.5)).toBe(OCCUPANCY.free);
    expect(along(1.5)).toBe(OCCUPANCY.free);
    const cellAt = along;
    expect(cellAt(-1)).toBe(OCCUPANCY.unknown);
  });

  it("puts a namespaced robot's perception under its namespace", async () => {
    const recording = await recordLooks(1, 'cube-2');
    expect(recording.channels.has(`/cube-2${PERCEPTION_TOPICS.objects}`)).toBe(true);
    expect(recording.channels.has(`/cube-2${PERCEPTION_TOPICS.grid}`)).toBe(true);
    expect(recording.channels.has(PERCEPTION_TOPICS.objects)).toBe(false);
  });
});
