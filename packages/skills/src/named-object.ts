import { COLOUR_NAMES } from '@hal/perception';
import type { ColourName, ObjectKind } from '@hal/perception';

/** The object an instruction names, in words perception's memory understands. */
export interface NamedObject {
  /** Undefined for a kind alone ("the pillar": see targetOf). */
  colour: ColourName | undefined;
  /** `unknown` when the instruction names a colour only ("the red thing"). */
  kind: ObjectKind;
  /** The words to ask the memory with, e.g. `red box`. */
  query: string;
  /** How near to stop, metres, when the instruction says ("within 25 cm"). */
  withinM?: number;
}

const KIND_WORDS: Readonly<Record<string, ObjectKind>> = {
  box: 'box',
  cube: 'box',
  crate: 'box',
  pillar: 'pillar',
  cylinder: 'pillar',
  column: 'pillar',
  post: 'pillar',
  pole: 'pillar',
};

/** Words allowed between a colour and its kind ("the red wooden box"). */
const BETWEEN = 2;

/**
 * The object an instruction asks the robot to go to: the first colour word with the kind word
 * that follows it within two words ("Drive to the red box and stop within 25 cm" gives red
 * box, 0.25 m). Undefined when the instruction names no colour.
 */
export function namedObject(instruction: string): NamedObject | undefined {
  const words = instruction
    .toLowerCase()
    .replace(/[^a-z0-9. ]/g, ' ')
    .split(/\s+/)
    .map((w) => w.replace(/\.$/, ''))
    .filter((w) => w !== '');
  const colours: readonly string[] = COLOUR_NAMES;
  const at = words.findIndex((w) => colours.includes(w));
  if (at === -1) return undefined;
  const colour = words[at] as ColourName;
  let kind: ObjectKind = 'unknown';
  for (const w of words.slice(at + 1, at + 2 + BETWEEN)) {
    const k = KIND_WORDS[w.replace(/s$/, '')];
    if (k !== undefined) {
      kind = k;
      break;
    }
  }
  const named: NamedObject = {
    colour,
    kind,
    query: kind === 'unknown' ? colour : `${colour} ${kind}`,
  };
  const within = withinM(instruction);
  if (within !== undefined) named.withinM = within;
  return named;
}

/** The distance after "within" ("within 25 cm", "within 0.3 m"), metres. */
function withinM(instruction: string): number | undefined {
  const within = /within\s+(\d+(?:\.\d+)?)\s*(cm|m|centimetres|centimeters|metres|meters)\b/i.exec(
    instruction,
  );
  if (within === null) return undefined;
  const n = Number(within[1]);
  return (within[2] ?? '').startsWith('c') ? n / 100 : n;
}

/** A point an instruction asks the robot to reach, in its pose's frame, metres. */
export interface NamedPoint {
  x: number;
  y: number;
  /** How near counts, metres, when the instruction says ("within 5 cm"). */
  withinM?: number;
}

/**
 * The point an instruction names in numbers ("Reach the point x = -0.3 m, y = 0 m, ... within 5
 * cm"), or undefined when it names none.
 */
export function namedPoint(instruction: string): NamedPoint | undefined {
  const match =
    /\bx\s*=\s*(-?\d+(?:\.\d+)?)\s*m?\s*,?\s*(?:and\s+)?y\s*=\s*(-?\d+(?:\.\d+)?)/i.exec(
      instruction,
    );
  if (match === null) return undefined;
  const point: NamedPoint = { x: Number(match[1]), y: Number(match[2]) };
  const within = withinM(instruction);
  if (within !== undefined) point.withinM = within;
  return point;
}
