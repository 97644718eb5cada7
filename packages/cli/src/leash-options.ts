// The leash on the command line: the options of every command that hands the robot to a model
// (`hal mcp`, `hal agent`). Parsing only; @hal/tools enforces the leash.
import type { Leash } from '@hal/tools';
import { InvalidArgumentError } from 'commander';
import type { Command } from 'commander';

/** A commander parser of a finite number, its errors naming `what`. */
export function numberOption(what: string) {
  return (text: string): number => {
    const value = Number(text);
    if (text.trim() === '' || !Number.isFinite(value)) {
      throw new InvalidArgumentError(`${what} must be a number`);
    }
    return value;
  };
}

function geofence(text: string): NonNullable<Leash['geofence']> {
  const parts = text.split(',').map(Number);
  const [minX, maxX, minY, maxY] = parts;
  if (
    parts.length !== 4 ||
    parts.some((p) => !Number.isFinite(p)) ||
    minX === undefined ||
    maxX === undefined ||
    minY === undefined ||
    maxY === undefined ||
    minX >= maxX ||
    minY >= maxY
  ) {
    throw new InvalidArgumentError('the geofence is minX,maxX,minY,maxY in metres, min < max');
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
      '--max-distance <m>',
      'leash: longest path of one motion, metres',
      numberOption('--max-distance'),
    )
    .option(
      '--max-speed <m/s>',
      'leash: fastest wheel speed of one call',
      numberOption('--max-speed'),
    )
    .option(
      '--geofence <minX,maxX,minY,maxY>',
      'leash: a motion must end inside, metres',
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
