// The leash on the command line: the options of every command that hands the robot to a model
// (`hal mcp`, `hal agent`). Parsing only; @hal/tools enforces the leash.
import type { Leash } from '@hal/tools';
import type { Command } from 'commander';
import { distanceArg, numberArg, readQuantity, usageError } from './values.js';

const GEOFENCE_FORM =
  '"--geofence" is minX,maxX,minY,maxY (metres, or each with a unit: 30cm), min < max';

function geofence(text: string): NonNullable<Leash['geofence']> {
  const parts = text.split(',').map((p) => readQuantity(p, 'distance'));
  const [minX, maxX, minY, maxY] = parts;
  if (
    parts.length !== 4 ||
    minX === undefined ||
    maxX === undefined ||
    minY === undefined ||
    maxY === undefined ||
    minX >= maxX ||
    minY >= maxY
  ) {
    throw usageError(`${GEOFENCE_FORM}, got "${text}"`);
  }
  return { minX, maxX, minY, maxY };
}

/** The leash options as commander parses them. */
export interface LeashCliOptions {
  maxDistance?: number;
  maxSpeed?: number;
  geofence?: NonNullable<Leash['geofence']>;
}

/** Adds --max-distance, --max-speed and --geofence to `command`. */
export function addLeashOptions(command: Command): Command {
  return command
    .option(
      '--max-distance <distance>',
      'leash: longest path of one motion (metres, or 30cm)',
      distanceArg('--max-distance', { min: 0 }),
    )
    .option(
      '--max-speed <m/s>',
      'leash: fastest wheel speed of one call, m/s',
      numberArg('--max-speed', { min: 0 }, 'm/s'),
    )
    .option(
      '--geofence <minX,maxX,minY,maxY>',
      'leash: a motion must end inside (metres, or each with a unit)',
      geofence,
    );
}

/** The leash the parsed options ask for (empty when none was given). */
export function leashFromOptions(options: LeashCliOptions): Leash {
  const leash: Leash = {};
  if (options.maxDistance !== undefined) leash.maxDistanceM = options.maxDistance;
  if (options.maxSpeed !== undefined) leash.maxSpeedMPerS = options.maxSpeed;
  if (options.geofence !== undefined) leash.geofence = options.geofence;
  return leash;
}
