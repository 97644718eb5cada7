// The calibration procedure on a connected robot: a measured straight line, then a measured
// full turn in place, each one HAL motion within the firmware's step limit (the HAL keeps the
// link alive with heartbeats while the user measures); then the new geometry is sent to the
// robot and returned. Ctrl-C during a motion stops the robot.
import type { PhysicalHAL } from '@hal/physical';
import { HalError, withTimeout } from '@hal/types';
import type { HALToolResult } from '@hal/types';
import { z } from 'zod';
import { CliError } from '../cli-error.js';
import { progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { aborted } from '../wait.js';
import { computeCalibration } from './calibration-math.js';
import type { WheelGeometry } from './calibration-math.js';
import type { Prompter } from './prompt.js';

/** A full turn: long enough that a few degrees of reading error stay under 1%. */
export const TURN_DEG = 360;
/** How long a stop after Ctrl-C may take. */
const STOP_WAIT_MS = 5000;

export interface CalibrationPlan {
  /** The straight line to drive, cm. */
  distanceCm: number;
  /** Given on the command line (scripts); else asked after the motion. */
  measuredDistanceCm?: number;
  measuredTurnDeg?: number;
  /** Asks the user (absent when both measurements are given). */
  prompter?: Prompter;
}

export interface CalibrationRun {
  before: WheelGeometry;
  after: WheelGeometry;
  straight: { leftSteps: number; rightSteps: number; predictedCm: number; measuredCm: number };
  turn: { leftSteps: number; rightSteps: number; predictedDeg: number; measuredDeg: number };
}

const StepsSchema = z.object({ leftSteps: z.number().int(), rightSteps: z.number().int() });

/** Micrometres are far below what a tape measure reads: no more digits than that are kept. */
const round4 = (value: number) => Math.round(value * 1e4) / 1e4;

function geometry(hal: PhysicalHAL): WheelGeometry {
  const { stepsPerRevolution, wheelDiameterCm, wheelBaseCm } = hal.robotConfig;
  return { stepsPerRevolution, wheelDiameterCm, wheelBaseCm };
}

/** Runs one motion; Ctrl-C stops the robot; a failure is the HAL's own error. */
async function motion(
  hal: PhysicalHAL,
  io: CliIO,
  call: () => Promise<HALToolResult>,
): Promise<{ leftSteps: number; rightSteps: number }> {
  const running = call();
  const first = await Promise.race([
    running,
    aborted(io.signal).then(() => 'interrupted' as const),
  ]);
  if (first === 'interrupted') {
    const stopped = await withTimeout(
      hal.locomotion.stop().then((r) => r.success),
      STOP_WAIT_MS,
    ).then(
      (answer) => answer?.value === true,
      () => false,
    );
    throw new CliError(
      'FAILED',
      stopped
        ? 'calibration interrupted: the robot was stopped; nothing was changed'
        : 'calibration interrupted: the robot did not confirm the stop; nothing was changed',
      130,
    );
  }
  if (!first.success) {
    throw new HalError(first.code ?? 'HARDWARE_ERROR', first.error ?? 'the motion failed');
  }
  const steps = StepsSchema.safeParse(first.data);
  if (!steps.success) {
    throw new HalError('MALFORMED', 'the motion result did not say how many steps the wheels made');
  }
  return steps.data;
}

async function measured(
  given: number | undefined,
  prompter: Prompter | undefined,
  question: string,
  unit: string,
): Promise<number> {
  if (given !== undefined) return given;
  if (prompter === undefined) throw new CliError('USAGE', `no measurement given (${unit})`);
  return await prompter.positive(question, unit);
}

/**
 * Drives the straight line and the turn, computes the geometry (refusing implausible
 * measurements before anything is sent) and applies it to the robot with `set_config`.
 */
export async function runCalibration(
  hal: PhysicalHAL,
  plan: CalibrationPlan,
  io: CliIO,
  global: GlobalOptions,
): Promise<CalibrationRun> {
  const before = geometry(hal);
  const say = (text: string) => progress(io, global, text);
  const { prompter } = plan;

  say(
    `1/2 straight line: mark the floor at the wheel axle; the robot drives ${plan.distanceCm} cm forward.`,
  );
  if (prompter !== undefined) await prompter.line('    press Enter when it has room to go ');
  const straight = await motion(hal, io, () => hal.locomotion.moveForward(plan.distanceCm));
  say(`    done: ${straight.leftSteps} and ${straight.rightSteps} steps (left, right)`);
  const measuredCm = await measured(
    plan.measuredDistanceCm,
    prompter,
    '    distance it actually travelled, cm: ',
    'cm',
  );

  say(
    `2/2 full turn: mark the robot's heading; it turns ${TURN_DEG} degrees left (counter-clockwise) in place.`,
  );
  if (prompter !== undefined) await prompter.line('    press Enter to turn ');
  const turn = await motion(hal, io, () => hal.locomotion.rotate('left', TURN_DEG));
  say(`    done: ${turn.leftSteps} and ${turn.rightSteps} steps (left, right)`);
  const measuredDeg = await measured(
    plan.measuredTurnDeg,
    prompter,
    '    angle it actually turned, degrees (more than 360 if it went past the mark): ',
    'degrees',
  );

  const result = computeCalibration(before, { ...straight, measuredCm }, { ...turn, measuredDeg });
  const applied = await hal.applyCalibration({
    wheelDiameterCm: round4(result.wheelDiameterCm),
    wheelBaseCm: round4(result.wheelBaseCm),
  });
  return {
    before,
    after: {
      stepsPerRevolution: applied.stepsPerRevolution,
      wheelDiameterCm: applied.wheelDiameterCm,
      wheelBaseCm: applied.wheelBaseCm,
    },
    straight: { ...straight, predictedCm: result.predictedCm, measuredCm },
    turn: { ...turn, predictedDeg: result.predictedDeg, measuredDeg },
  };
}
