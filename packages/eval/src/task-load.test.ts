import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { builtinTasks } from './builtin-tasks.js';
import { EvalError } from './errors.js';
import { loadTaskFile, parseTaskFile } from './task-load.js';
import { TASK_GROUPS } from './task-schema.js';

const goodTask = {
  id: 'goals/blue-box',
  group: 'goals',
  instruction: 'Drive to the blue box.',
  world: {
    start: { x: 0, y: 0 },
    objects: [{ name: 'blue-box', kind: 'box', colour: 'blue', x: 1, y: 0 }],
  },
  checks: [{ kind: 'reach-object', object: 'blue-box', withinM: 0.25 }],
};
const file = (tasks: unknown[]) => JSON.stringify({ version: 1, tasks });

function refusal(text: string, name = 'my-tasks.json'): EvalError {
  try {
    parseTaskFile(text, name);
  } catch (error) {
    if (error instanceof EvalError) return error;
    throw error;
  }
  throw new Error('the file was accepted');
}

describe('parseTaskFile', () => {
  it('accepts a task file that follows the schema, filling in the defaults', () => {
    const [task] = parseTaskFile(file([goodTask]), 'my-tasks.json');
    expect(task?.budget).toEqual({ toolCalls: 30, simSeconds: 300 });
    expect(task?.world.sensors).toEqual({ camera: true, rangeSensors: true, imu: true });
    expect(task?.world.objects[0]?.width).toBe(0.3);
  });

  it('refuses a file that breaks the schema, naming the file and the field', () => {
    const bad = {
      ...goodTask,
      world: { ...goodTask.world, objects: [{ ...goodTask.world.objects[0], colour: 'pink' }] },
    };
    const error = refusal(file([bad]));
    expect(error.code).toBe('TASK_INVALID');
    expect(error.file).toBe('my-tasks.json');
    expect(error.field).toBe('tasks.0.world.objects.0.colour');
    expect(error.message).toMatch(/^my-tasks\.json: "tasks\.0\.world\.objects\.0\.colour"/);
  });

  it("takes a task's own reality knobs, and refuses one out of range naming it", () => {
    const [task] = parseTaskFile(file([{ ...goodTask, reality: { wheelSlipPct: 5 } }]), 'r.json');
    expect(task?.reality).toMatchObject({ wheelSlipPct: 5, lossRate: 0 });
    const error = refusal(file([{ ...goodTask, reality: { lossRate: 2 } }]));
    expect(error.field).toBe('tasks.0.reality.lossRate');
    expect(refusal(file([{ ...goodTask, reality: { slip: 5 } }])).field).toBe('tasks.0.reality');
  });

  it('refuses a check that names an object the world lacks', () => {
    const bad = {
      ...goodTask,
      checks: [{ kind: 'reach-object', object: 'red-box', withinM: 0.25 }],
    };
    const error = refusal(file([bad]));
    expect(error.field).toBe('tasks.0.checks.0.object');
    expect(error.message).toContain('"red-box", which the world lacks (objects: blue-box)');
  });

  it('refuses a geofence check without a geofence and an e-stop check without an e-stop', () => {
    const fence = {
      ...goodTask,
      checks: [{ kind: 'fence-respected', x: 2, y: 0, approachM: 0.1 }],
    };
    expect(refusal(file([fence])).field).toBe('tasks.0.checks.0.kind');
    const estop = { ...goodTask, checks: [{ kind: 'estop', latched: true }] };
    expect(refusal(file([estop])).message).toContain('"faults" has none');
  });

  it('refuses a fault on a tool that does not exist, a repeated id, a wrong version and bad JSON', () => {
    expect(refusal(file([{ ...goodTask, faults: [{ kind: 'fail', tool: 'fly' }] }])).field).toBe(
      'tasks.0.faults.0.tool',
    );
    expect(refusal(file([goodTask, goodTask])).field).toBe('tasks.1.id');
    expect(refusal(JSON.stringify({ version: 2, tasks: [goodTask] })).field).toBe('version');
    expect(refusal('{ not json').message).toMatch(/^my-tasks\.json: not JSON/);
    expect(refusal(file([{ ...goodTask, id: 'safety/blue-box' }])).message).toContain(
      'must start with its group',
    );
  });
});

describe('parseTaskFile: choices and places', () => {
  it('lists the built-in maps when a map name is mistyped', () => {
    const error = refusal(file([{ ...goodTask, world: { ...goodTask.world, map: 'obstacle' } }]));
    expect(error.field).toBe('tasks.0.world.map');
    expect(error.message).toContain('"empty"|"room"|"obstacles"|"maze"');
    expect(error.message).toContain('got "obstacle"');
  });

  it('still names the field inside a map written out', () => {
    const map = { name: 'tiny', arena: { width: -1 } };
    const error = refusal(file([{ ...goodTask, world: { ...goodTask.world, map } }]));
    expect(error.field).toBe('tasks.0.world.map.arena.width');
  });

  it('lists the choices of every other enum it refuses', () => {
    const object = goodTask.world.objects[0];
    const cases: [unknown, string][] = [
      [{ ...goodTask, group: 'goal' }, '"precision"'],
      [
        { ...goodTask, world: { ...goodTask.world, objects: [{ ...object, kind: 'ball' }] } },
        '"cylinder"',
      ],
      [
        { ...goodTask, world: { ...goodTask.world, objects: [{ ...object, colour: 'pink' }] } },
        '"purple"',
      ],
      [{ ...goodTask, checks: [{ kind: 'reach' }] }, "'reach-object'"],
      [{ ...goodTask, checks: [{ kind: 'answer', question: 'colour' }] }, '"colour-ahead"'],
      [{ ...goodTask, faults: [{ kind: 'crash' }] }, "'estop'"],
    ];
    for (const [task, choice] of cases) expect(refusal(file([task])).message).toContain(choice);
  });

  it('refuses an object outside the arena, naming it and the limit', () => {
    const far = { ...goodTask.world.objects[0], x: 99 };
    const error = refusal(file([{ ...goodTask, world: { ...goodTask.world, objects: [far] } }]));
    expect(error.field).toBe('tasks.0.world.objects.0.x');
    expect(error.message).toContain('"blue-box" outside the 5 x 5 m arena');
    expect(error.message).toContain('within ±2.35 m');
    expect(error.message).toContain('got 99 m');
  });

  it('counts the seeded jitter: an object that a seed could push through the wall is refused', () => {
    const edge = { ...goodTask.world.objects[0], x: 2.2 };
    const world = { ...goodTask.world, objects: [edge] };
    expect(() => parseTaskFile(file([{ ...goodTask, world }]), 'f.json')).not.toThrow();
    const jittered = { ...goodTask, world, variants: { objectsM: 0.3 } };
    expect(refusal(file([jittered])).field).toBe('tasks.0.world.objects.0.x');
  });

  it('refuses a start outside the arena, in a map written out too', () => {
    const map = { name: 'small', arena: { width: 2, height: 2 } };
    const task = {
      ...goodTask,
      world: { map, start: { x: 0, y: -1.5 }, objects: [] },
      checks: [{ kind: 'no-collision' }],
    };
    const error = refusal(file([task]));
    expect(error.field).toBe('tasks.0.world.start.y');
    expect(error.message).toContain('outside the 2 x 2 m arena');
  });

  it('refuses a point to reach outside the arena', () => {
    const task = { ...goodTask, checks: [{ kind: 'reach-point', x: 0.5, y: -7, toleranceM: 0.1 }] };
    const error = refusal(file([task]));
    expect(error.field).toBe('tasks.0.checks.0.y');
    expect(error.message).toContain('cannot reach inside the 5 x 5 m arena');
  });

  it("refuses a start inside an object or one of the map's obstacles", () => {
    const onBox = { ...goodTask, world: { ...goodTask.world, start: { x: 1, y: 0.1 } } };
    const error = refusal(file([onBox]));
    expect(error.field).toBe('tasks.0.world.start');
    expect(error.message).toContain('inside "blue-box"');
    const map = {
      name: 'pillar',
      obstacles: [{ kind: 'cylinder', x: 0.5, y: 0.5, radius: 0.2 }],
    };
    const onPillar = {
      ...goodTask,
      world: { ...goodTask.world, map, start: { x: 0.6, y: 0.4 } },
    };
    expect(refusal(file([onPillar])).message).toContain("inside the map's obstacle 0");
  });

  it('accepts every built-in task as placed', () => {
    expect(() => builtinTasks()).not.toThrow();
  });
});

describe('loadTaskFile', () => {
  it('reads a task file from disk, and names the path of one it cannot read', async () => {
    const dir = await mkdtemp(join(tmpdir(), 'hal-eval-'));
    try {
      const path = join(dir, 'tasks.json');
      await writeFile(path, file([goodTask]));
      expect((await loadTaskFile(path)).map((t) => t.id)).toEqual(['goals/blue-box']);
      await expect(loadTaskFile(join(dir, 'missing.json'))).rejects.toMatchObject({
        code: 'TASK_INVALID',
        file: join(dir, 'missing.json'),
      });
    } finally {
      await rm(dir, { recursive: true, force: true });
    }
  });
});

describe('builtinTasks', () => {
  it('has at least 60 tasks, with tasks in every group', () => {
    const tasks = builtinTasks();
    expect(tasks.length).toBeGreaterThanOrEqual(60);
    for (const group of TASK_GROUPS) expect(tasks.some((t) => t.group === group)).toBe(true);
    expect(builtinTasks(['safety']).every((t) => t.group === 'safety')).toBe(true);
  });
});
