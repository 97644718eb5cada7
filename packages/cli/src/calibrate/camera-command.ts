// `hal calibrate camera`: fits a physical robot's camera tilt (and lens height, from two or more
// distances) to a coloured target standing straight ahead at a measured distance, and saves the
// camera model in the robot's calibration file, which every later command loads with the wheels
// (the HAL reports it in getDeviceInfo, perception projects with it).
import { Command, Option } from 'commander';
import { calibrationDir, calibrationPath, PhysicalHAL } from '@hal/physical';
import { COLOUR_NAMES } from '@hal/perception';
import type { ColourName } from '@hal/perception';
import { HalError } from '@hal/types';
import type { CameraModel } from '@hal/types';
import { CliError } from '../cli-error.js';
import { emit, progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import { distanceArg, integerArg, positiveArg } from '../values.js';
import { updateCalibrationFile, tolerantSource } from './calibration-store.js';
import { canPrompt, prompter } from './prompt.js';
import { runCameraCalibration } from './run-camera-calibration.js';
import type { CameraCalibrationRun } from './run-camera-calibration.js';

interface CameraCalibrateOptions extends TargetCliOptions {
  distance: number[];
  colour: ColourName;
  frames: number;
  cameraHeight?: number;
  calibrationDir?: string;
  save: boolean;
  answerTimeout: number;
}

export interface CameraCalibrateDocument extends CameraCalibrationRun {
  deviceId: string;
  /** The calibration file written (absent with --no-save). */
  file?: string;
}

const DISTANCE = { min: 0.1, max: 5 } as const;

/** Collects each `--distance` given, in metres. */
function distances(value: string, previous: number[] | undefined): number[] {
  return [...(previous ?? []), distanceArg('--distance', DISTANCE)(value)];
}

const cm = (m: number) => `${(m * 100).toFixed(1)} cm`;
const deg = (d: number) => `${d.toFixed(2)} degrees`;

function cameraText(doc: CameraCalibrateDocument): string {
  const { before, after } = doc;
  return [
    `robot ${doc.deviceId}: camera calibrated on the ${doc.colour} target`,
    ...doc.sightings.map(
      (s) =>
        `  at ${cm(s.distanceM)}: base at row ${s.row}, the fitted camera puts it at ${cm(s.predictedM)}`,
    ),
    `  tilt         ${deg(before.tiltDeg)} -> ${deg(after.tiltDeg)}`,
    doc.fittedHeight
      ? `  lens height  ${cm(before.heightM)} -> ${cm(after.heightM)}`
      : `  lens height  ${cm(after.heightM)} (not fitted: give two distances at least 10 cm apart)`,
    `  residual     ${(doc.residualM * 1000).toFixed(1)} mm`,
    doc.file === undefined
      ? '  not saved (--no-save)'
      : `  saved to ${doc.file}: hal uses this camera model for this robot from now on`,
  ].join('\n');
}

/** The `camera` subcommand of `hal calibrate`. */
export function cameraCalibrateCommand(io: CliIO, global: () => GlobalOptions): Command {
  const command = new Command('camera')
    .description(
      "fit a physical robot's camera tilt (and lens height) to a coloured target standing straight ahead at a measured distance",
    )
    .addOption(
      new Option(
        '--distance <distance>',
        "from the robot's centre to the target's near face, e.g. 50cm; twice or more (the target moved between) fits the lens height too",
      ).argParser(distances),
    )
    .addOption(
      new Option('--colour <colour>', 'the colour of the target')
        .choices(COLOUR_NAMES)
        .default('red'),
    )
    .addOption(
      new Option('--frames <n>', 'frames looked at per distance')
        .argParser(integerArg('--frames', 1, 50))
        .default(5),
    )
    .addOption(
      new Option(
        '--camera-height <distance>',
        'the lens height above the floor, measured (then only the tilt is fitted)',
      ).argParser(distanceArg('--camera-height', { min: 0.005, max: 2 })),
    )
    .addOption(
      new Option(
        '--calibration-dir <dir>',
        'where calibration files are kept (default $HAL_CALIBRATION_DIR, else $XDG_CONFIG_HOME/hal/calibration, else ~/.config/hal/calibration)',
      ),
    )
    .addOption(new Option('--no-save', 'report the fitted camera only; write no file'))
    .addOption(
      new Option('--answer-timeout <s>', 'give up when a question is not answered within this')
        .argParser(positiveArg('--answer-timeout'))
        .default(600),
    );
  const kinds = ['udp', 'serial'] as const;
  addTargetOptions(command, kinds, { calibration: false }).action(
    async (options: CameraCalibrateOptions) => {
      const target = resolveTarget(options, io.env, kinds);
      const json = global().json;
      const given = options.distance ?? [];
      if (given.length === 0) {
        throw new CliError(
          'USAGE',
          "give --distance: how far the target's near face is from the robot's centre, e.g. --distance 50cm",
        );
      }
      // the target is moved between distances: only a person at a terminal can do that
      const interactive = given.length > 1;
      if (interactive && (json || !canPrompt(io))) {
        throw new CliError(
          'USAGE',
          'two or more --distance values need a terminal (the target is moved between them); give one in a script',
        );
      }
      const dir = options.calibrationDir ?? calibrationDir(io.env);
      const connect =
        options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
      const ask = interactive ? prompter(io, options.answerTimeout * 1000) : undefined;
      try {
        const doc = await withTarget(
          target,
          io,
          { ...connect, json, calibration: tolerantSource(dir, io, json) },
          async ({ hal, deviceId }): Promise<CameraCalibrateDocument> => {
            if (!(hal instanceof PhysicalHAL)) {
              throw new HalError('NOT_IMPLEMENTED', 'hal calibrate camera needs a physical robot');
            }
            const camera: CameraModel | undefined = hal.getDeviceInfo().camera;
            if (camera === undefined) {
              throw new CliError(
                'USAGE',
                "the robot has no camera to calibrate: give its ESP32-CAM's --camera-url",
              );
            }
            // before looking: an id that cannot name the file would lose the measurement
            const path = options.save ? calibrationPath(dir, deviceId) : undefined;
            progress(io, { json }, `calibrating the camera of robot ${deviceId}`);
            const run = await runCameraCalibration(
              hal,
              camera,
              {
                distancesM: given,
                colour: options.colour,
                frames: options.frames,
                ...(options.cameraHeight === undefined ? {} : { heightM: options.cameraHeight }),
                ...(ask === undefined ? {} : { prompter: ask }),
              },
              io,
              { json },
            );
            if (path === undefined) return { deviceId, ...run };
            const now = new Date().toISOString();
            await updateCalibrationFile(path, deviceId, io, json, (old) => ({
              ...old,
              calibratedAt: now,
              camera: {
                model: run.after,
                calibratedAt: now,
                residualM: run.residualM,
                measurements: run.sightings.map((s) => ({
                  colour: run.colour,
                  distanceM: s.distanceM,
                  baseRow: s.row,
                })),
              },
            }));
            return { deviceId, ...run, file: path };
          },
        );
        emit(io, { json }, doc, () => cameraText(doc));
      } finally {
        ask?.close();
      }
    },
  );
  return command;
}
