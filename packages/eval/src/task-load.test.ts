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
  it('has at least 20 tasks, with tasks in every group', () => {
    const tasks = builtinTasks();
    expect(tasks.length).toBeGreaterThanOrEqual(20);
    for (const group of TASK_GROUPS) expect(tasks.some((t) => t.group === group)).toBe(true);
    expect(builtinTasks(['safety']).every((t) => t.group === 'safety')).toBe(true);
  });
});
