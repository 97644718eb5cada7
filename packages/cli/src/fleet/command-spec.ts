// `--command` for `hal fleet run`: a short form people type (forward:0.05 or forward:5cm,
// rotate:left:90, moveTo:0.5,0.2) or a fleet command as JSON; both become a checked FleetCommand.
// Distances and angles read as in every other command: a bare number is metres or degrees.
import { parseFleetCommand } from '@hal/fleet';
import type { FleetCommand } from '@hal/fleet';
import { isHalError, motionCall } from '@hal/types';
import { CliError } from '../cli-error.js';
import { readNumber, readQuantity } from '../values.js';
import type { QuantityKind } from '../values.js';

export const COMMAND_SPEC_HELP =
  'forward:<distance> | backward:<distance> (metres, or 5cm) | rotate:<left|right>:<angle> ' +
  '(degrees, or 1.5rad) | moveTo:<x>,<y>[,<m/s>] (metres, or with a unit) | ' +
  'drive:<left>,<right>[,<ms>] (power -255..255) | led:<r>,<g>,<b> | stop | a JSON fleet command';

/**
 * The comma-separated values of `text`: each read as `kinds[i]` (a distance or angle with an
 * optional unit) or, past the kinds given, as a plain number; USAGE when any is not.
 */
function numbers(
  text: string | undefined,
  count: [number, number],
  spec: string,
  kinds: readonly QuantityKind[] = [],
): number[] {
  const parts = (text ?? '').split(',').map((p) => p.trim());
  const values = parts.map((p, i) => {
    const kind = kinds[i];
    return kind === undefined ? readNumber(p) : readQuantity(p, kind);
  });
  if (
    text === undefined ||
    parts.length < count[0] ||
    parts.length > count[1] ||
    values.some((v) => v === undefined)
  ) {
    throw new CliError('USAGE', `--command "${spec}": expected ${COMMAND_SPEC_HELP}`);
  }
  return values as number[];
}

/** Parses `--command`; a malformed one is a USAGE error that names the accepted forms. */
export function parseCommandSpec(spec: string): FleetCommand {
  const text = spec.trim();
  let raw: unknown;
  if (text.startsWith('{')) {
    try {
      raw = JSON.parse(text);
    } catch {
      throw new CliError('USAGE', `--command: not valid JSON: ${text}`);
    }
  } else {
    const [verb = '', ...rest] = text.split(':');
    const arg = rest.join(':');
    const word = verb.toLowerCase();
    switch (word) {
      case 'forward':
      case 'backward': {
        // the verb is the motion: the table's straight drive that way
        const [metres = 0] = numbers(arg, [1, 1], text, ['distance']);
        raw = { kind: motionCall(word).name, distanceCm: Number((metres * 100).toPrecision(12)) };
        break;
      }
      case 'rotate': {
        const [direction, degrees] = arg.split(':');
        const [value] = numbers(degrees, [1, 1], text, ['angle']);
        raw = { kind: 'rotate', direction, degrees: value };
        break;
      }
      case 'moveto': {
        const [x, y, speed] = numbers(arg, [2, 3], text, ['distance', 'distance']);
        raw = { kind: 'moveTo', x, y, ...(speed === undefined ? {} : { speed }) };
        break;
      }
      case 'drive': {
        const [left, right, durationMs] = numbers(arg, [2, 3], text);
        raw = { kind: 'drive', left, right, ...(durationMs === undefined ? {} : { durationMs }) };
        break;
      }
      case 'led': {
        const [r, g, b] = numbers(arg, [3, 3], text);
        raw = { kind: 'setLED', r, g, b };
        break;
      }
      case 'stop':
        raw = { kind: 'stop' };
        break;
      default:
        throw new CliError('USAGE', `--command "${text}": expected ${COMMAND_SPEC_HELP}`);
    }
  }
  try {
    return parseFleetCommand(raw);
  } catch (error) {
    if (isHalError(error)) throw new CliError('USAGE', `--command "${text}": ${error.message}`);
    throw error;
  }
}
