import { TOOL_CATALOG } from '@hal/tools';
import { parseJsonText, readTextFile, refuse } from './task-file-io.js';
import { answerProblem } from './task-answers.js';
import { placementProblem } from './task-bounds.js';
import { ANY_MOTION, TaskFileSchema } from './task-schema.js';
import type { Task } from './task-schema.js';

// every tool of the call table; a call added there is a tool a fault may name
const TOOL_NAMES: ReadonlySet<string> = new Set(TOOL_CATALOG.map((tool) => tool.name));

/** Refuses a task whose checks or faults name something its world or leash lacks. */
function checkReferences(file: string, task: Task, at: string): void {
  const names = new Set<string>();
  task.world.objects.forEach((o, i) => {
    if (names.has(o.name)) refuse(file, `${at}.world.objects.${i}.name`, `repeats "${o.name}"`);
    names.add(o.name);
  });
  task.checks.forEach((check, i) => {
    const where = `${at}.checks.${i}`;
    if (check.kind === 'reach-object' && !names.has(check.object)) {
      const known = [...names].join(', ') || 'none';
      refuse(
        file,
        `${where}.object`,
        `names "${check.object}", which the world lacks (objects: ${known})`,
      );
    }
    if (check.kind === 'fence-respected' && task.leash?.geofence === undefined)
      refuse(file, `${where}.kind`, 'needs a geofence, but the task has no "leash.geofence"');
    if (check.kind === 'estop' && !task.faults.some((f) => f.kind === 'estop'))
      refuse(file, `${where}.kind`, 'needs an e-stop during the task, but "faults" has none');
    if (check.kind === 'answer') {
      const boxes = task.world.objects.filter((o) => o.kind === 'box').length;
      if (check.question === 'count-boxes' && boxes === 0)
        refuse(file, `${where}.question`, 'asks to count boxes, but the world has no box objects');
      if (check.question === 'colour-ahead' && names.size === 0)
        refuse(file, `${where}.question`, 'asks for a colour, but the world has no objects');
    }
  });
  task.faults.forEach((fault, i) => {
    if (fault.kind !== 'estop' && fault.tool !== ANY_MOTION && !TOOL_NAMES.has(fault.tool))
      refuse(
        file,
        `${at}.faults.${i}.tool`,
        `names "${fault.tool}", which is no tool (tools: ${[...TOOL_NAMES].join(', ')}, or "${ANY_MOTION}")`,
      );
  });
  const misplaced = placementProblem(task);
  if (misplaced !== undefined) refuse(file, `${at}.${misplaced.field}`, misplaced.why);
  const unanswerable = answerProblem(task);
  if (unanswerable !== undefined) refuse(file, `${at}.${unanswerable.field}`, unanswerable.why);
}

/**
 * Parses the text of a task file (JSON) named `file`; throws TASK_INVALID naming the file and
 * the first field that breaks the schema or names something the world lacks.
 */
export function parseTaskFile(text: string, file: string): Task[] {
  const json = parseJsonText(text, file);
  return checkTaskFile(json, file);
}

/** Checks an already parsed task file; see {@link parseTaskFile}. */
export function checkTaskFile(json: unknown, file: string): Task[] {
  const parsed = TaskFileSchema.safeParse(json);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    const field = issue?.path.map(String).join('.') || '(file)';
    refuse(file, field, issue?.message ?? 'is invalid');
  }
  const ids = new Set<string>();
  parsed.data.tasks.forEach((task, i) => {
    if (ids.has(task.id)) refuse(file, `tasks.${i}.id`, `repeats "${task.id}"`);
    ids.add(task.id);
    if (!task.id.startsWith(`${task.group}/`))
      refuse(file, `tasks.${i}.id`, `must start with its group "${task.group}/"`);
    checkReferences(file, task, `tasks.${i}`);
  });
  return parsed.data.tasks;
}

/** Reads and checks a task file from disk (Node). */
export async function loadTaskFile(path: string): Promise<Task[]> {
  return parseTaskFile(await readTextFile(path), path);
}
