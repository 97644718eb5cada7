/*
 * Reading a perception answer for what it commits to. A model answers in sentences: "I count 3
 * boxes and 2 pillars", "The left is open; the right is blocked", "There is a red box ahead and
 * a blue pillar to the left". The answer is the value the sentence ties to the question's words
 * (boxes, open or blocked, ahead), else the first value stated; two different values offered as
 * alternatives ("red or blue", "maybe 3, maybe 4") commit to nothing.
 */

import type { Question } from './task-schema.js';

export type { Question };

const COLOUR_WORDS = ['red', 'green', 'blue', 'yellow', 'purple', 'orange'];
const NUMBER_WORDS = [
  'zero',
  'one',
  'two',
  'three',
  'four',
  'five',
  'six',
  'seven',
  'eight',
  'nine',
  'ten',
];
const SIDES = ['left', 'right'];
const AHEAD_WORDS = new Set(['ahead', 'front', 'straight', 'forward']);
const BOX_WORDS = new Set(['box', 'boxes', 'cube', 'cubes']);
const PILLAR_WORDS = new Set(['pillar', 'pillars', 'cylinder', 'cylinders', 'column', 'columns']);
const ID_BEFORE = new Set(['box', 'cube', 'cylinder', 'pillar', 'object', 'obstacle', 'id', '#']);
const UNITS = new Set(['m', 'cm', 'mm', 'metre', 'metres', 'meter', 'meters', 'deg', 'degrees']);
const OPEN_WORDS = new Set(['open', 'free', 'clear', 'empty', 'unobstructed', 'nothing']);
const BLOCKED_WORDS = new Set([
  'blocked',
  'closed',
  'obstructed',
  'wall',
  'occupied',
  'box',
  'obstacle',
  'something',
]);
const NEGATIONS = new Set(['not', 'no', 'nt', 'isn', 'never']);
const HEDGES =
  /\b(or|either|maybe|perhaps|possibly|probably|could be|might be|not sure|unsure)\b|\//;

/** The clauses of an answer (split at sentence ends, commas, colons, "and", "but"), as words. */
function clauses(text: string): string[][] {
  return text
    .toLowerCase()
    .replace(/n't\b/g, ' not')
    .split(/[.;:!?,\n()]+(?!\d)|\b(?:and|but|while|whereas)\b/)
    .map((c) => c.match(/[a-z]+|\d+(?:\.\d+)?|#/g) ?? [])
    .filter((c) => c.length > 0);
}

/** The value a word names for the question, if any. */
function valueOf(word: string, question: Question): string | undefined {
  if (question === 'colour-ahead' || question === 'colour-of')
    return COLOUR_WORDS.includes(word) ? word : undefined;
  if (question === 'open-side') return SIDES.includes(word) ? word : undefined;
  if (/^\d+$/.test(word)) return String(Number(word));
  const i = NUMBER_WORDS.indexOf(word);
  return i >= 0 ? String(i) : undefined;
}

/** Whether the word at `i` of a clause is a count (not an id like "box 2", not "0.5 m"). */
function isCount(clause: readonly string[], i: number): boolean {
  const word = clause[i] ?? '';
  if (valueOf(word, 'count-boxes') === undefined) return false;
  if (ID_BEFORE.has(clause[i - 1] ?? '')) return false;
  return !UNITS.has(clause[i + 1] ?? '');
}

/**
 * The count a clause ties to the kind's words ("3 boxes", "boxes: 3", "no boxes"; the same for
 * pillars), if any.
 */
function kindCount(clause: readonly string[], words: ReadonlySet<string>): string | undefined {
  for (let i = 0; i < clause.length; i += 1) {
    if (!words.has(clause[i] ?? '')) continue;
    // a count before the box word, at most two words before it ("3 small boxes")
    for (let j = i - 1; j >= Math.max(0, i - 3); j -= 1) {
      if (isCount(clause, j)) return valueOf(clause[j] ?? '', 'count-boxes');
      if (clause[j] === 'no' && j === i - 1) return '0';
    }
    // or after it ("the boxes number 3", "boxes 3" is an id, so not straight after)
    for (let j = i + 2; j < Math.min(clause.length, i + 5); j += 1)
      if (isCount(clause, j)) return valueOf(clause[j] ?? '', 'count-boxes');
  }
  return undefined;
}

/** The side a clause says is open ("the left is open", "a wall on the right"), if any. */
function openSideOf(clause: readonly string[]): string | undefined {
  const side = clause.find((w) => SIDES.includes(w));
  if (side === undefined) return undefined;
  const negated = clause.some((w) => NEGATIONS.has(w));
  const open = clause.some((w) => OPEN_WORDS.has(w));
  const blocked = clause.some((w) => BLOCKED_WORDS.has(w));
  if (open === blocked) return undefined;
  const other = side === 'left' ? 'right' : 'left';
  return open !== negated ? side : other;
}

const isCountQuestion = (q: Question) => q === 'count-boxes' || q === 'count-pillars';

/** Every value the answer names, in order (for the hedging test). */
function allValues(parts: readonly string[][], question: Question): string[] {
  const out: string[] = [];
  for (const clause of parts)
    clause.forEach((w, i) => {
      if (isCountQuestion(question) && !isCount(clause, i)) return;
      const v = valueOf(w, question);
      if (v !== undefined) out.push(v);
    });
  return out;
}

/**
 * What `answer` commits to for `question`: a colour name, a count in digits or `left` / `right`
 * (the open side); undefined when it names none, or hedges between different values.
 */
export function readAnswer(answer: string, question: Question): string | undefined {
  const parts = clauses(answer);
  const values = allValues(parts, question);
  if (new Set(values).size > 1 && HEDGES.test(answer.toLowerCase())) return undefined;
  if (isCountQuestion(question)) {
    const words = question === 'count-boxes' ? BOX_WORDS : PILLAR_WORDS;
    for (const clause of parts) {
      const n = kindCount(clause, words);
      if (n !== undefined) return n;
    }
    return values[0];
  }
  if (question === 'open-side') {
    for (const clause of parts) {
      const side = openSideOf(clause);
      if (side !== undefined) return side;
    }
    return values[0];
  }
  const notNegated = (clause: readonly string[]) =>
    clause.filter((w, i) => COLOUR_WORDS.includes(w) && !NEGATIONS.has(clause[i - 1] ?? ''));
  // of a named object ("the box you passed") there is no "ahead" to prefer: the first colour
  if (question === 'colour-of') return parts.map(notNegated).find((c) => c.length > 0)?.[0];
  for (const clause of parts) {
    const colour = notNegated(clause)[0];
    if (colour !== undefined && clause.some((w) => AHEAD_WORDS.has(w))) return colour;
  }
  return parts.map(notNegated).find((c) => c.length > 0)?.[0];
}
