// The steps of `hal record`: each argument one action in `hal drive`'s words and units
// ("forward 0.1" or "forward 10cm", "turn 90" or "turn 1.5rad", "move-to 0.2 0.1",
// "wheels 100 100 500", "stop", "estop why", "reset-estop"), checked against the robot's limits
// before anything is sent.
import { CliError } from '../cli-error.js';
import { checkAction } from '../drive/actions.js';
import type { DriveAction } from '../drive/actions.js';
import { article, QUANTITY_FORMS, readNumber, readQuantity } from '../values.js';
import type { QuantityKind } from '../values.js';

/** A word of `step` as a number, or as a distance or angle with its unit; USAGE when not. */
function number(step: string, word: string | undefined, what: string, kind?: QuantityKind): number {
  const n =
    word === undefined
      ? undefined
      : kind === undefined
        ? readNumber(word)
        : readQuantity(word, kind);
  if (n === undefined) {
    const form = kind === undefined ? 'a number' : `${article(kind)} (${QUANTITY_FORMS[kind]})`;
    throw new CliError(
      'USAGE',
      `step "${step}": ${what} must be ${form}, got ${word === undefined ? 'nothing' : `"${word}"`}`,
    );
  }
  return n;
}

function arity(step: string, words: string[], count: number): void {
  if (words.length !== count) {
    throw new CliError(
      'USAGE',
      `step "${step}" takes ${count} number${count === 1 ? '' : 's'}, got ${words.length}`,
    );
  }
}

/** One step as typed, as the action it names; USAGE for anything else. */
export function parseStep(step: string): DriveAction {
  const [kind, ...rest] = step.trim().split(/\s+/);
  let action: DriveAction;
  switch (kind) {
    case 'forward':
      arity(step, rest, 1);
      action = { kind, metres: number(step, rest[0], 'the distance', 'distance') };
      break;
    case 'turn':
      arity(step, rest, 1);
      action = { kind, degrees: number(step, rest[0], 'the angle', 'angle') };
      break;
    case 'move-to':
      arity(step, rest, 2);
      action = {
        kind,
        x: number(step, rest[0], 'x', 'distance'),
        y: number(step, rest[1], 'y', 'distance'),
      };
      break;
    case 'wheels':
      arity(step, rest, 3);
      action = {
        kind,
        left: number(step, rest[0], 'the left power'),
        right: number(step, rest[1], 'the right power'),
        durationMs: number(step, rest[2], 'the duration'),
      };
      break;
    case 'stop':
    case 'reset-estop':
      arity(step, rest, 0);
      action = { kind };
      break;
    case 'estop':
      action = rest.length === 0 ? { kind } : { kind, reason: rest.join(' ') };
      break;
    default:
      throw new CliError(
        'USAGE',
        `unknown step "${step}": one of forward DISTANCE, turn ANGLE, move-to X Y, wheels L R MS, stop, estop [REASON], reset-estop (a distance in metres or with a unit, 30cm; an angle in degrees or with a unit, 1.5rad)`,
      );
  }
  checkAction(action);
  return action;
}
