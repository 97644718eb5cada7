// Every answer check must have a true answer in every member of the task's family: a colour
// question with nothing ahead of the start, or a side question with both sides about as open,
// could never be passed (or only by a coin toss), and its 0 would be blamed on the agent. The
// loader asks the question of the task as written and of a fixed set of seeds.
import { castRay, solidsOf } from '@hal/simulation';
import { inArea, trueAnswer } from './checks.js';
import type { Check, Task } from './task-schema.js';
import { realiseTask } from './variant.js';
import type { TaskVariant } from './variant.js';

/** The seeds the loader realises each task with an answer check at (the eval's own start at 1). */
export const ANSWER_SEEDS = 32;

/** Least difference between the free distance to the left and to the right, metres. */
export const OPEN_SIDE_MARGIN_M = 0.1;

type AnswerCheck = Extract<Check, { kind: 'answer' }>;

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

/**
 * What is wrong with what an answer check asks about (its object, its area), whatever the seed,
 * or undefined: a colour asked of no object, of one the world lacks or one a seed may leave out;
 * a count of a kind the world (or the area) has none of; an object or area the question ignores.
 */
function subjectProblem(task: Task, check: AnswerCheck, i: number): AnswerProblem | undefined {
  const at = `checks.${i}`;
  const counting = check.question === 'count-boxes' || check.question === 'count-pillars';
  if (check.question === 'colour-of') {
    if (check.object === undefined)
      return { field: `${at}.object`, why: 'is missing: a "colour-of" question names its object' };
    if (!task.world.objects.some((o) => o.name === check.object)) {
      const known = task.world.objects.map((o) => o.name).join(', ') || 'none';
      return {
        field: `${at}.object`,
        why: `names "${check.object}", which the world lacks (objects: ${known})`,
      };
    }
    if (task.variants.maybeObjects.includes(check.object))
      return {
        field: `${at}.object`,
        why: `names "${check.object}", which "variants.maybeObjects" lets a seed leave out (then it has no colour)`,
      };
  } else if (check.object !== undefined) {
    return { field: `${at}.object`, why: `is only for "colour-of", not "${check.question}"` };
  }
  if (check.area !== undefined && !counting)
    return {
      field: `${at}.area`,
      why: `is only for "count-boxes" and "count-pillars", not "${check.question}"`,
    };
  if (counting) {
    const { area } = check;
    const [kind, word] =
      check.question === 'count-boxes' ? ['box', 'boxes'] : ['cylinder', 'pillars'];
    if (!task.world.objects.some((o) => o.kind === kind && inArea(area, o.x, o.y)))
      return {
        field: `${at}.question`,
        why: `asks to count ${word}, but the world has no ${kind} objects${area === undefined ? '' : ' in the area'}`,
      };
  }
  return undefined;
}

/** The first answer check of `task` that has no true answer for some variant, or undefined. */
export function answerProblem(task: Task): AnswerProblem | undefined {
  for (const [i, check] of task.checks.entries()) {
    if (check.kind !== 'answer') continue;
    const problem = subjectProblem(task, check, i);
    if (problem !== undefined) return problem;
  }
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
    if (check.kind !== 'answer') continue;
    if (check.question !== 'colour-ahead' && check.question !== 'open-side') continue;
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
