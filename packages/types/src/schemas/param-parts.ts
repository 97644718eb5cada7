import { z } from 'zod';
import {
  maxDistancePerCommandCm,
  maxLinearSpeedMPerS,
  maxRotationPerCommandDeg,
  minLinearSpeedMPerS,
} from '../robot-config.js';
import type { RobotConfig } from '../robot-config.js';

/** Rounds a limit down so the number quoted to users is never above the true limit. */
function floorTo(value: number, decimals: number): number {
  const scale = 10 ** decimals;
  return Math.floor(value * scale) / scale;
}

/** Rounds a lower limit up so the number quoted to users is never below the true limit. */
function ceilTo(value: number, decimals: number): number {
  const scale = 10 ** decimals;
  return Math.ceil(value * scale) / scale;
}

/**
 * The limits of a robot configuration as the call table's parameter schemas quote them (rounded
 * so a quoted limit is never beyond the true one), and the parameters several calls share.
 */
export interface ParamParts {
  /** Largest turn of one command, degrees. */
  readonly maxDeg: number;
  /** Slowest and fastest cruise speeds, m/s. */
  readonly minSpeed: number;
  readonly maxSpeed: number;
  /** Half the side of the square workspace, metres. */
  readonly extent: number;
  /** Longest timed wheel drive, ms. */
  readonly maxDriveDurationMs: number;
  /** A straight drive's distance, cm, up to one command's limit. */
  readonly distanceCm: z.ZodNumber;
  /** A wheel's power, -255..255. */
  power(wheel: string): z.ZodNumber;
}

/** The parameter parts for `config`. */
export function paramParts(config: RobotConfig): ParamParts {
  const maxCm = floorTo(maxDistancePerCommandCm(config), 1);
  const maxSpeed = floorTo(maxLinearSpeedMPerS(config), 4);
  return {
    maxDeg: floorTo(maxRotationPerCommandDeg(config), 1),
    minSpeed: Math.min(ceilTo(minLinearSpeedMPerS(config), 4), maxSpeed),
    maxSpeed,
    extent: config.workspaceHalfExtentM,
    maxDriveDurationMs: config.maxDriveDurationMs,
    distanceCm: z
      .number()
      .gt(0)
      .max(maxCm)
      .describe(`Distance, cm, greater than 0 and at most ${maxCm} (one command's limit)`),
    power: (wheel) =>
      z
        .number()
        .min(-255)
        .max(255)
        .describe(`${wheel} wheel power, -255..255 (negative: backwards; 255 = top speed)`),
  };
}
