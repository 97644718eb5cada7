// Every answer check must have a true answer in every member of the task's family: a colour
// question with nothing ahead of the start, or a side question with both sides about as open,
// could never be passed (or only by a coin toss), and its 0 would be blamed on the agent. The
// loader asks the question of the task as written and of a fixed set of seeds.
import { castRay, solidsOf } from '@hal/simulation';
import { trueAnswer } from './checks.js';
import type { Task } from './task-schema.js';
import { realiseTask } from './variant.js';
import type { TaskVariant } from './variant.js';

/** The seeds the loader realises each task with an answer check at (the eval's own start at 1). */
export const ANSWER_SEEDS = 32;

/** Least difference between the free distance to the left and to the right, metres. */
export const OPEN_SIDE_MARGIN_M = 0.1;

/** An answer check without a true answer: the field and why. */
export interface AnswerProblem {
  field: string;
  why: string;
}

const round = (v: number) => Math.round(v * 1000) / 1000;

/** What is wrong with the question in this variant, or undefined when it has a clear answer. */
function unanswerable(
  variant: TaskVariant,
  question: 'colour-ahead' | 'open-side',
): string | undefined {
  if (question === 'colour-ahead')
    return trueAnswer(variant, question) === 'none' ? 'nothing is ahead of the start' : undefined;
  const { x, y, yaw } = variant.start;
  const solids = solidsOf(variant.map);
  const left = castRay(x, y, yaw + Math.PI / 2, 100, solids).distance;
  const right = castRay(x, y, yaw - Math.PI / 2, 100, solids).distance;
  return Math.abs(left - right) < OPEN_SIDE_MARGIN_M
    ? `neither side of the start is the open one (${round(left)} m free to the left, ${round(right)} m to the right; they must differ by ${OPEN_SIDE_MARGIN_M} m)`
    : undefined;
}

/** The first answer check of `task` that has no true answer for some variant, or undefined. */
export function answerProblem(task: Task): AnswerProblem | undefined {
  const still: Task = {
    ...task,
    variants: {
      ...task.variants,
      startM: 0,
      yawDeg: 0,
      objectsM: 0,
      maybeObjects: [],
      mirror: false,
    },
  };
  for (const [i, check] of task.checks.entries()) {
    if (check.kind !== 'answer' || check.question === 'count-boxes') continue;
    const field = `checks.${i}.question`;
    const { x, y, yawDeg } = task.world.start;
    const written = unanswerable(realiseTask(still, 0), check.question);
    if (written !== undefined)
      return {
        field,
        why: `is ${check.question}, but ${written}, at (${round(x)}, ${round(y)}) facing ${round(yawDeg)}°`,
      };
    for (let seed = 0; seed < ANSWER_SEEDS; seed += 1) {
      const drawn = unanswerable(realiseTask(task, seed), check.question);
      if (drawn === undefined) continue;
      return {
        field,
        why: `is ${check.question}, but with seed ${seed} (start ± ${round(task.variants.startM)} m, heading ± ${round(task.variants.yawDeg)}°, objects ± ${round(task.variants.objectsM)} m) ${drawn}`,
      };
    }
  }
  return undefined;
}
