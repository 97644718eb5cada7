import type { NamedObject } from './named-object.js';
import { namedObject } from './named-object.js';

const KIND_ONLY = /\b(box|cube|crate|pillar|cylinder|column|post|pole)(e?s)?\b/i;

/**
 * The thing a skill's `target` names, in the memory's words: a colour and maybe a kind ("the red
 * box", "green"), or a kind alone ("the pillar"). Undefined when it names neither.
 */
export function targetOf(text: string): NamedObject | undefined {
  const named = namedObject(text);
  if (named !== undefined) return named;
  const kind = KIND_ONLY.exec(text)?.[1]?.toLowerCase();
  if (kind === undefined) return undefined;
  const pillar = ['pillar', 'cylinder', 'column', 'post', 'pole'].includes(kind);
  return pillar
    ? { colour: undefined, kind: 'pillar', query: 'pillar' }
    : { colour: undefined, kind: 'box', query: 'box' };
}

/** Why a target was not understood, for the model. */
export const TARGET_HELP =
  'name a thing by its colour and kind, e.g. "red box" or "blue pillar" (colours: red, green, blue, yellow, orange, purple)';
