import { COLOUR_NAMES } from './palette.js';
import type { ColourName } from './palette.js';
import type { ObjectKind } from './seen-object.js';

/*
 * A vision model's words for an object ("red box", "Purple cylinder", "a crimson crate") mapped to
 * perception's palette colour and kind. A label names the first colour word it has; words that
 * mean one of the palette's colours count as it (crimson is red, violet is purple); any other
 * colour is not one perception can name.
 */

/** The kinds a vision model is asked to tell apart. */
export const VLM_KINDS = ['box', 'pillar'] as const;
export type VlmKind = (typeof VLM_KINDS)[number];

const COLOUR_WORDS: Readonly<Record<string, ColourName>> = Object.freeze({
  ...Object.fromEntries(COLOUR_NAMES.map((name) => [name, name])),
  crimson: 'red',
  scarlet: 'red',
  amber: 'orange',
  gold: 'yellow',
  golden: 'yellow',
  violet: 'purple',
  magenta: 'purple',
  navy: 'blue',
});

/** Colour words that are not the palette's: the label names a colour, just another one. */
const OTHER_COLOUR_WORDS = new Set([
  'white',
  'black',
  'grey',
  'gray',
  'brown',
  'pink',
  'cyan',
  'teal',
  'beige',
  'silver',
]);

const KIND_WORDS: Readonly<Record<string, VlmKind>> = Object.freeze({
  box: 'box',
  boxes: 'box',
  cube: 'box',
  crate: 'box',
  block: 'box',
  pillar: 'pillar',
  cylinder: 'pillar',
  column: 'pillar',
  post: 'pillar',
  pole: 'pillar',
  can: 'pillar',
  tube: 'pillar',
});

/** What a label says: the palette colour it names (or none, or another colour), and the kind. */
export type LabelReading =
  | { colour: ColourName; kind: ObjectKind }
  | { colour: undefined; otherColour: string | undefined; kind: ObjectKind };

/**
 * Reads a model's label. `colours` and `kinds` are the vocabulary asked for: a palette colour
 * outside `colours` reads as another colour, a kind outside `kinds` as `unknown`.
 */
export function readLabel(
  label: string,
  colours: readonly ColourName[] = COLOUR_NAMES,
  kinds: readonly VlmKind[] = VLM_KINDS,
): LabelReading {
  const words = label
    .toLowerCase()
    .split(/[^a-z]+/)
    .filter((w) => w !== '');
  let kind: ObjectKind = 'unknown';
  for (const word of words) {
    const k = KIND_WORDS[word];
    if (k !== undefined && kinds.includes(k)) {
      kind = k;
      break;
    }
  }
  for (const word of words) {
    const colour = COLOUR_WORDS[word];
    if (colour !== undefined) {
      return colours.includes(colour)
        ? { colour, kind }
        : { colour: undefined, otherColour: word, kind };
    }
    if (OTHER_COLOUR_WORDS.has(word)) return { colour: undefined, otherColour: word, kind };
  }
  return { colour: undefined, otherColour: undefined, kind };
}
