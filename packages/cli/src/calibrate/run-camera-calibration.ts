// The camera calibration on a connected robot: a coloured target straight ahead at each measured
// distance (asked for between distances when there are several), found in the camera's frames
// by perception's colour segmentation; the camera's tilt (and, from two or more distances, its
// lens height) fitted so that the target's base projects to the measured distance. The robot
// does not move.
import type { ColourName } from '@hal/perception';
import type { CameraModel, HardwareAbstractionLayer } from '@hal/types';
import { CliError } from '../cli-error.js';
import { progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { fitCamera } from './camera-fit.js';
import { findTarget } from './camera-target.js';
import type { Prompter } from './prompt.js';

export interface CameraCalibrationPlan {
  /** Measured distances from the robot's centre to the target's near face, m (one or more). */
  distancesM: number[];
  colour: ColourName;
  /** Frames looked at per distance. */
  frames: number;
  /** The lens height to assume, m (default the robot's model's); never fitted when given. */
  heightM?: number;
  /** Asks the user to move the target between distances (needed for more than one). */
  prompter?: Prompter;
}

/** One distance's sighting and what the fitted model makes of it. */
export interface CameraSightingReport {
  distanceM: number;
  /** The target's base row and column in the image, pixels (medians over `frames`). */
  row: number;
  column: number;
  frames: number;
  /** Where the fitted model puts the base, m. */
  predictedM: number;
}

export interface CameraCalibrationRun {
  colour: ColourName;
  before: CameraModel;
  after: CameraModel;
  /** Whether the lens height was fitted (two or more distances and no --camera-height). */
  fittedHeight: boolean;
  /** The largest |predicted - measured| over the distances, m. */
  residualM: number;
  sightings: CameraSightingReport[];
}

const cm = (m: number) => `${(m * 100).toFixed(1)} cm`;

/** Finds the target at each distance and fits the camera model to the sightings. */
export async function runCameraCalibration(
  hal: HardwareAbstractionLayer,
  camera: CameraModel,
  plan: CameraCalibrationPlan,
  io: CliIO,
  global: GlobalOptions,
): Promise<CameraCalibrationRun> {
  const say = (text: string) => progress(io, global, text);
  const base = plan.heightM === undefined ? camera : { ...camera, heightM: plan.heightM };
  const found = [];
  for (const [i, distanceM] of plan.distancesM.entries()) {
    const step = `${i + 1}/${plan.distancesM.length}`;
    const where = `the ${plan.colour} target straight ahead, its near face ${cm(distanceM)} from the robot's centre`;
    if (plan.prompter !== undefined) {
      say(`${step} place ${where}.`);
      await plan.prompter.line('    press Enter when it is in place ');
    } else {
      say(`${step} looking for ${where}`);
    }
    if (io.signal.aborted) throw new CliError('FAILED', 'calibration interrupted', 130);
    const seen = await findTarget(hal, camera, plan.colour, { frames: plan.frames });
    say(
      `    its base is at row ${seen.row}, column ${seen.column.toFixed(0)} (${seen.frames} frames)`,
    );
    found.push({ distanceM, ...seen });
  }
  // with --camera-height the height is given: only the tilt is fitted
  const fit = fitCamera(base, found, { keepHeight: plan.heightM !== undefined });
  return {
    colour: plan.colour,
    before: camera,
    after: fit.model,
    fittedHeight: fit.fittedHeight,
    residualM: fit.residualM,
    sightings: found.map((s, i) => ({ ...s, predictedM: fit.predictedM[i] ?? Number.NaN })),
  };
}
