import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { builtinTasks } from './builtin-tasks.js';
import { EvalError } from './errors.js';
import { realiseTask } from './variant.js';
import { loadWorldFile, parseWorldFile, realiseWorld } from './world-file.js';

const WORLD = {
  map: 'empty',
  start: { x: 0.5, y: -0.25, yawDeg: 90 },
  objects: [{ name: 'red-box', kind: 'box', colour: 'red', x: 1, y: 0 }],
};

describe('world files', () => {
  it('realises a world as written: its objects in the map, the start in radians', () => {
    const world = realiseWorld(parseWorldFile(JSON.stringify(WORLD), 'w.json'));
    expect(world.start).toEqual({ x: 0.5, y: -0.25, yaw: Math.PI / 2 });
    expect(world.map.starts).toEqual([world.start]);
    const box = world.map.obstacles.at(-1);
    expect(box).toMatchObject({ kind: 'box', x: 1, y: 0, width: 0.3, depth: 0.3, height: 0.3 });
    expect(world.objects.map((o) => o.name)).toEqual(['red-box']);
  });

  it("makes the same map of a task's world as the task's variant with nothing moved", () => {
    const task = builtinTasks().find((t) => t.world.objects.length > 0)!;
    const still = { ...task, variants: { ...task.variants, startM: 0, yawDeg: 0, objectsM: 0 } };
    expect(realiseWorld(task.world).map).toEqual(realiseTask(still, 1).map);
  });

  it('names the file and the first bad field', () => {
    const bad = { ...WORLD, objects: [{ ...WORLD.objects[0], colour: 'mauve' }] };
    expect(() => parseWorldFile(JSON.stringify(bad), 'w.json')).toThrow(
      /w\.json: "objects\.0\.colour"/,
    );
    expect(() => parseWorldFile('{', 'w.json')).toThrow(/w\.json: not JSON/);
    const twice = { ...WORLD, objects: [WORLD.objects[0], WORLD.objects[0]] };
    expect(() => parseWorldFile(JSON.stringify(twice), 'w.json')).toThrow(/repeats "red-box"/);
  });

  it('reads a file from disk, and says when it cannot', async () => {
    const dir = await mkdtemp(join(tmpdir(), 'hal-world-'));
    try {
      const file = join(dir, 'world.json');
      await writeFile(file, JSON.stringify(WORLD));
      expect((await loadWorldFile(file)).objects).toHaveLength(1);
      const missing = loadWorldFile(join(dir, 'none.json'));
      await expect(missing).rejects.toBeInstanceOf(EvalError);
      await expect(missing).rejects.toThrow(/cannot be read/);
    } finally {
      await rm(dir, { recursive: true, force: true });
    }
  });
});
