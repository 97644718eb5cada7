// The wheel geometry from two measured motions: a straight line (all wheel travel is distance)
// gives the wheel diameter; a turn in place (each wheel on a circle of the wheel base) then gives
// the wheel base. Both from the steps the robot reports it made, not from the command's nominal.
import { HalError } from '@hal/types';

/** The wheel geometry a measurement starts from (the robot's present values). */
export interface WheelGeometry {
  stepsPerRevolution: number;
  wheelDiameterCm: number;
  wheelBaseCm: number;
}

/** A straight drive: the steps each wheel made and the distance the user measured. */
export interface StraightRun {
  leftSteps: number;
  rightSteps: number;
  measuredCm: number;
}

/** A turn in place: the steps each wheel made (opposite signs) and the angle measured. */
export interface TurnRun {
  leftSteps: number;
  rightSteps: number;
  measuredDeg: number;
}

/** What a calibration found, with what the old geometry predicted for the same steps. */
export interface CalibrationResult {
  wheelDiameterCm: number;
  wheelBaseCm: number;
  /** The distance the old geometry predicted for the straight run's steps, cm. */
  predictedCm: number;
  /** The angle the old geometry predicted for the turn's steps, degrees. */
  predictedDeg: number;
}

/**
 * A measurement further than this factor from the prediction is refused: a real wheel is never
 * twice or half its nominal size, so it is a typo, a wrong unit or a slipping wheel.
 */
export const MAX_RATIO = 2;

function invalid(parameter: string, message: string, received: unknown): HalError {
  return new HalError('INVALID_PARAMETER', message, { details: { parameter, received } });
}

function positive(parameter: string, value: number, unit: string): number {
  if (!Number.isFinite(value) || value <= 0) {
    throw invalid(parameter, `"${parameter}" must be a number > 0 ${unit}, got ${value}`, value);
  }
  return value;
}

function steps(parameter: string, value: number): number {
  if (!Number.isInteger(value) || value === 0) {
    throw invalid(parameter, `"${parameter}" must be a non-zero whole number of steps`, value);
  }
  return Math.abs(value);
}

function plausible(parameter: string, measured: number, predicted: number, unit: string): void {
  const ratio = measured / predicted;
  if (ratio > MAX_RATIO || ratio < 1 / MAX_RATIO) {
    throw invalid(
      parameter,
      `"${parameter}" ${measured} ${unit} is more than ${MAX_RATIO}x from the ${predicted.toFixed(1)} ${unit} ` +
        'the robot was told to move: measure again (in the right unit)',
      measured,
    );
  }
}

/**
 * The calibrated wheel diameter and base: for the straight run,
 * diameter = measured x steps_per_rev / (pi x steps); for the turn, with each wheel s steps along
 * a circle of the wheel base b, angle = 360 x (s x pi x diameter / steps_per_rev) / (pi x b), so
 * b = 360 x s x diameter / (steps_per_rev x measured angle). INVALID_PARAMETER for NaN, zero or
 * negative measurements, steps that are not a straight line or a turn in place, or a measurement
 * more than {@link MAX_RATIO}x from what `before` predicted.
 */
export function computeCalibration(
  before: WheelGeometry,
  straight: StraightRun,
  turn: TurnRun,
): CalibrationResult {
  const spr = positive('stepsPerRevolution', before.stepsPerRevolution, 'steps');
  const d0 = positive('wheelDiameterCm', before.wheelDiameterCm, 'cm');
  const b0 = positive('wheelBaseCm', before.wheelBaseCm, 'cm');
  const measuredCm = positive('measuredDistanceCm', straight.measuredCm, 'cm');
  const measuredDeg = positive('measuredTurnDeg', turn.measuredDeg, 'degrees');

  const sl = steps('straight leftSteps', straight.leftSteps);
  const sr = steps('straight rightSteps', straight.rightSteps);
  if (Math.sign(straight.leftSteps) !== Math.sign(straight.rightSteps)) {
    throw invalid('straight', 'the straight run turned its wheels opposite ways', straight);
  }
  const tl = steps('turn leftSteps', turn.leftSteps);
  const tr = steps('turn rightSteps', turn.rightSteps);
  if (Math.sign(turn.leftSteps) === Math.sign(turn.rightSteps)) {
    throw invalid('turn', 'the turn did not turn the wheels opposite ways', turn);
  }

  const straightSteps = (sl + sr) / 2;
  const turnSteps = (tl + tr) / 2;
  const predictedCm = (straightSteps * Math.PI * d0) / spr;
  plausible('measuredDistanceCm', measuredCm, predictedCm, 'cm');
  const wheelDiameterCm = (measuredCm * spr) / (Math.PI * straightSteps);
  const predictedDeg = (360 * turnSteps * d0) / (spr * b0);
  plausible('measuredTurnDeg', measuredDeg, predictedDeg, 'degrees');
  const wheelBaseCm = (360 * turnSteps * wheelDiameterCm) / (spr * measuredDeg);
  return { wheelDiameterCm, wheelBaseCm, predictedCm, predictedDeg };
}
