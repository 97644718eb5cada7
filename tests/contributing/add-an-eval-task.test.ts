// CONTRIBUTING.md, "Add an eval task", done once: a version-1 task file written to a folder of
// its own, loaded and checked as `hal eval --tasks-file` loads it, run with the oracle (a task
// the oracle cannot solve is one to fix), and refused, naming the file and the field, once it is
// broken. Then what shipping it with the package means, checked on the files that ship: every
// task file under packages/eval/src/tasks is loaded by builtin-tasks.ts, each task in its group.
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { builtinTasks, loadTaskFile, oracleAgent, runEval, TASK_FILE_VERSION } from '@hal/eval';

const dir = mkdtempSync(join(tmpdir(), 'hal-contributing-task-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** The new task: out 25 cm, a quarter turn left, and the robot must end facing +y of its start. */
const TASK_FILE = {
  version: 1,
  tasks: [
    {
      id: 'precision/out-and-left',
      group: 'precision',
      instruction: 'Drive forward 25 cm, then turn left 90 degrees on the spot.',
      world: { map: 'empty', start: { x: 0, y: 0, yawDeg: 0 } },
      variants: { startM: 0.3, yawDeg: 180 },
      budget: { toolCalls: 10, simSeconds: 60 },
      checks: [
        {
          kind: 'displacement',
          forwardM: 0.25,
          toleranceM: 0.01,
          headingDeg: 90,
          headingToleranceDeg: 2,
        },
      ],
    },
  ],
};

const packageRoot = new URL('../../packages/eval/src/', import.meta.url);

describe('a new eval task (CONTRIBUTING.md: Add an eval task)', () => {
  it('is loaded from its file and solved by the oracle on every seed tried', async () => {
    expect(TASK_FILE.version).toBe(TASK_FILE_VERSION);
    const file = join(dir, 'out-and-left.json');
    writeFileSync(file, `${JSON.stringify(TASK_FILE, null, 2)}\n`);
    const tasks = await loadTaskFile(file);
    expect(tasks.map((t) => t.id)).toEqual(['precision/out-and-left']);

    const report = await runEval({ tasks, agents: [oracleAgent()], trials: 3, seed: 1 });
    const [oracle] = report.scores.agents;
    expect(oracle?.trials).toHaveLength(3);
    for (const trial of oracle?.trials ?? []) {
      expect(trial.success, `seed ${trial.seed}: ${trial.failures.join('; ')}`).toBe(true);
    }
  }, 120_000);

  it('is refused at load when a field breaks the schema, naming the file and the field', async () => {
    const file = join(dir, 'broken.json');
    const broken = structuredClone(TASK_FILE);
    (broken.tasks[0]!.world as { map: string }).map = 'emptty';
    writeFileSync(file, JSON.stringify(broken));
    await expect(loadTaskFile(file)).rejects.toMatchObject({
      code: 'TASK_INVALID',
      field: 'tasks.0.world.map',
      message: expect.stringContaining('broken.json'),
    });
  });

  it('ships with the package once builtin-tasks.ts loads its file, as it loads every one', () => {
    const loader = readFileSync(new URL('builtin-tasks.ts', packageRoot), 'utf8');
    const files = readdirSync(new URL('tasks/', packageRoot)).filter((f) => f.endsWith('.json'));
    expect(files.length).toBeGreaterThan(0);
    const shipped = new Set(builtinTasks().map((t) => t.id));
    for (const name of files) {
      expect(loader, `builtin-tasks.ts imports tasks/${name}`).toContain(`'./tasks/${name}'`);
      expect(loader, `builtin-tasks.ts checks tasks/${name}`).toContain(`'tasks/${name}'`);
      const json = JSON.parse(
        readFileSync(new URL(`tasks/${name}`, packageRoot), 'utf8'),
      ) as typeof TASK_FILE;
      for (const task of json.tasks) {
        expect(shipped.has(task.id), `${task.id} of tasks/${name}`).toBe(true);
        expect(task.id.startsWith(`${task.group}/`), `${task.id} is named for its group`).toBe(
          true,
        );
      }
    }
  });
});
