// Every answer check must have a true answer in every member of the task's family: a colour
// question with nothing ahead of the start could never be passed, and its 0 would be blamed on
// the agent. The loader asks the question of the task as written and of a fixed set of seeds.
import { trueAnswer } from './checks.js';
import type { Task } from './task-schema.js';
import { realiseTask } from './variant.js';

/** The seeds the loader realises each task with an answer check at (the eval's own start at 1). */
export const ANSWER_SEEDS = 32;

/** An answer check without a true answer: the field and why. */
export interface AnswerProblem {
  field: string;
  why: string;
}

const round = (v: number) => Math.round(v * 1000) / 1000;

/** The first answer check of `task` that has no true answer for some variant, or undefined. */
export function answerProblem(task: Task): AnswerProblem | undefined {
  const still: Task = {
    ...task,
    variants: { ...task.variants, startM: 0, yawDeg: 0, objectsM: 0 },
  };
  for (const [i, check] of task.checks.entries()) {
    if (check.kind !== 'answer' || check.question !== 'colour-ahead') continue;
    const field = `checks.${i}.question`;
    const { x, y, yawDeg } = task.world.start;
    if (trueAnswer(realiseTask(still, 0), check.question) === 'none')
      return {
        field,
        why: `is colour-ahead, but nothing is ahead of the start (${round(x)}, ${round(y)}) facing ${round(yawDeg)}°: no object lies on that line before a wall`,
      };
    for (let seed = 0; seed < ANSWER_SEEDS; seed += 1) {
      if (trueAnswer(realiseTask(task, seed), check.question) !== 'none') continue;
      return {
        field,
        why: `is colour-ahead, but with seed ${seed} the jitter (start ± ${round(task.variants.startM)} m, heading ± ${round(task.variants.yawDeg)}°, objects ± ${round(task.variants.objectsM)} m) leaves nothing ahead of the start`,
      };
    }
  }
  return undefined;
}
