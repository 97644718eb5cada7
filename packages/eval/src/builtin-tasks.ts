import { checkTaskFile } from './task-load.js';
import type { Task, TaskGroup } from './task-schema.js';
import goals from './tasks/goals.json' with { type: 'json' };
import perception from './tasks/perception.json' with { type: 'json' };
import precision from './tasks/precision.json' with { type: 'json' };
import memory from './tasks/memory.json' with { type: 'json' };
import robustness from './tasks/robustness.json' with { type: 'json' };
import safety from './tasks/safety.json' with { type: 'json' };
import search from './tasks/search.json' with { type: 'json' };
import sequences from './tasks/sequences.json' with { type: 'json' };

let checked: readonly Task[] | undefined;

/**
 * The tasks that ship with the package, checked like any task file, group by group, on first use
 * (not at import: a program that imports the package but runs no evaluation, such as `hal --help`,
 * does not pay for checking every task), and only those of `groups` (all when empty or absent).
 */
export function builtinTasks(groups?: readonly TaskGroup[]): Task[] {
  checked ??= Object.freeze([
    ...checkTaskFile(precision, 'tasks/precision.json'),
    ...checkTaskFile(goals, 'tasks/goals.json'),
    ...checkTaskFile(perception, 'tasks/perception.json'),
    ...checkTaskFile(safety, 'tasks/safety.json'),
    ...checkTaskFile(robustness, 'tasks/robustness.json'),
    ...checkTaskFile(search, 'tasks/search.json'),
    ...checkTaskFile(memory, 'tasks/memory.json'),
    ...checkTaskFile(sequences, 'tasks/sequences.json'),
  ]);
  return checked.filter(
    (t) => groups === undefined || groups.length === 0 || groups.includes(t.group),
  );
}
