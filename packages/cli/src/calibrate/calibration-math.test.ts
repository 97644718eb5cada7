import { describe, expect, it } from 'vitest';
import { computeCalibration } from './calibration-math.js';

const V1 = { stepsPerRevolution: 4096, wheelDiameterCm: 6, wheelBaseCm: 10 };
/** Steps of a 100 cm drive and of a full left turn on the V1 geometry, as the firmware rounds them. */
const STRAIGHT = 21730;
const TURN = 6827;
const nominalCm = (STRAIGHT * Math.PI * 6) / 4096;
const nominalDeg = (360 * TURN * 6) / (4096 * 10);

describe('computeCalibration', () => {
  it('gives back the nominal geometry when the robot went exactly as far as its steps predicted', () => {
    const result = computeCalibration(
      V1,
      { leftSteps: STRAIGHT, rightSteps: STRAIGHT, measuredCm: nominalCm },
      { leftSteps: -TURN, rightSteps: TURN, measuredDeg: nominalDeg },
    );
    expect(result.wheelDiameterCm).toBeCloseTo(6, 12);
    expect(result.wheelBaseCm).toBeCloseTo(10, 12);
    expect(result.predictedCm).toBeCloseTo(100, 1);
    expect(result.predictedDeg).toBeCloseTo(360, 0);
  });

  it('finds a 10% larger wheel when the robot went 10% further, and the base from the turn', () => {
    // the true robot: 6.6 cm wheels, 10.4 cm apart; the turn it made with the same steps
    const trueDeg = (360 * TURN * 6.6) / (4096 * 10.4);
    const result = computeCalibration(
      V1,
      { leftSteps: STRAIGHT, rightSteps: STRAIGHT, measuredCm: nominalCm * 1.1 },
      { leftSteps: -TURN, rightSteps: TURN, measuredDeg: trueDeg },
    );
    expect(result.wheelDiameterCm).toBeCloseTo(6.6, 10);
    expect(result.wheelBaseCm).toBeCloseTo(10.4, 10);
  });

  it('works from the steps the robot reports, in either direction, whatever the command', () => {
    const result = computeCalibration(
      { stepsPerRevolution: 4076, wheelDiameterCm: 6, wheelBaseCm: 10 },
      { leftSteps: -20000, rightSteps: -20002, measuredCm: 92 },
      { leftSteps: 7000, rightSteps: -7000, measuredDeg: 350 },
    );
    const d = (92 * 4076) / (Math.PI * 20001);
    expect(result.wheelDiameterCm).toBeCloseTo(d, 12);
    expect(result.wheelBaseCm).toBeCloseTo((360 * 7000 * d) / (4076 * 350), 12);
  });

  it.each([
    ['NaN', Number.NaN, /"measuredDistanceCm" must be a number > 0 cm, got NaN/],
    ['zero', 0, /"measuredDistanceCm" must be a number > 0 cm, got 0/],
    ['negative', -50, /"measuredDistanceCm" must be a number > 0 cm, got -50/],
    ['Infinity', Number.POSITIVE_INFINITY, /got Infinity/],
    ['absurdly short (a metre typed as 1)', 1, /more than 2x from the 100\.0 cm/],
    ['absurdly long (millimetres)', 1000, /more than 2x from the 100\.0 cm/],
  ])('refuses a measured distance that is %s', (_name, measuredCm, message) => {
    expect(() =>
      computeCalibration(
        V1,
        { leftSteps: STRAIGHT, rightSteps: STRAIGHT, measuredCm },
        { leftSteps: -TURN, rightSteps: TURN, measuredDeg: 360 },
      ),
    ).toThrow(
      expect.objectContaining({
        code: 'INVALID_PARAMETER',
        message: expect.stringMatching(message),
      }),
    );
  });

  it.each([
    ['NaN', Number.NaN, /"measuredTurnDeg" must be a number > 0 degrees, got NaN/],
    ['zero', 0, /got 0/],
    ['negative', -360, /got -360/],
    ['absurd (radians typed)', 6.28, /more than 2x from the 360\.0 degrees/],
    ['absurd (two turns counted)', 1080, /more than 2x/],
  ])('refuses a measured turn that is %s', (_name, measuredDeg, message) => {
    expect(() =>
      computeCalibration(
        V1,
        { leftSteps: STRAIGHT, rightSteps: STRAIGHT, measuredCm: 100 },
        { leftSteps: -TURN, rightSteps: TURN, measuredDeg },
      ),
    ).toThrow(
      expect.objectContaining({
        code: 'INVALID_PARAMETER',
        message: expect.stringMatching(message),
      }),
    );
  });

  it('refuses runs that were not a straight line and a turn in place', () => {
    const turn = { leftSteps: -TURN, rightSteps: TURN, measuredDeg: 360 };
    const straight = { leftSteps: STRAIGHT, rightSteps: STRAIGHT, measuredCm: 100 };
    expect(() =>
      computeCalibration(V1, { leftSteps: 0, rightSteps: 0, measuredCm: 100 }, turn),
    ).toThrow(/non-zero whole number of steps/);
    expect(() =>
      computeCalibration(V1, { leftSteps: 100, rightSteps: -100, measuredCm: 100 }, turn),
    ).toThrow(/opposite ways/);
    expect(() =>
      computeCalibration(V1, straight, { leftSteps: TURN, rightSteps: TURN, measuredDeg: 360 }),
    ).toThrow(/did not turn the wheels opposite ways/);
    expect(() => computeCalibration({ ...V1, wheelDiameterCm: 0 }, straight, turn)).toThrow(
      /"wheelDiameterCm" must be a number > 0/,
    );
  });
});
