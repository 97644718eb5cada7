// `hal calibrate`: measures a physical robot's wheel diameter and wheel base (a measured straight
// line, a measured full turn), sends them to the robot and saves them in the robot's calibration
// file, which every later command sends again after each hello. Scripts give the measurements as
// options; a person is asked for them. `hal calibrate camera` (calibrate/camera-command.ts) fits
// the camera model and saves it in the same file.
import { Command, Option } from 'commander';
import { calibrationDir, calibrationPath, PhysicalHAL } from '@hal/physical';
import { positiveArg } from '../values.js';
import { HalError } from '@hal/types';
import { cameraCalibrateCommand } from '../calibrate/camera-command.js';
import { tolerantSource, updateCalibrationFile } from '../calibrate/calibration-store.js';
import { canPrompt, prompter } from '../calibrate/prompt.js';
import { runCalibration, TURN_DEG } from '../calibrate/run-calibration.js';
import type { CalibrationRun } from '../calibrate/run-calibration.js';
import { CliError } from '../cli-error.js';
import { emit, progress } from '../io.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import type { RegisterCommand } from './context.js';

interface CalibrateOptions extends TargetCliOptions {
  distanceCm: number;
  measuredDistanceCm?: number;
  measuredTurnDeg?: number;
  calibrationDir?: string;
  save: boolean;
  answerTimeout: number;
}

/** The longest straight line asked for: well inside one command's 40960 steps on 6 cm wheels. */
const MAX_DISTANCE_CM = 150;
const MIN_DISTANCE_CM = 20;

function distanceArg(value: string): number {
  const n = positiveArg('--distance-cm')(value);
  if (n < MIN_DISTANCE_CM || n > MAX_DISTANCE_CM) {
    throw new CliError(
      'USAGE',
      `"--distance-cm" must be ${MIN_DISTANCE_CM}..${MAX_DISTANCE_CM} cm, got "${value}"`,
    );
  }
  return n;
}

export interface CalibrateDocument extends CalibrationRun {
  deviceId: string;
  /** The calibration file written (absent with --no-save). */
  file?: string;
}

const cm = (value: number) => `${value.toFixed(3)} cm`;

function calibrateText(doc: CalibrateDocument): string {
  const { before, after, straight, turn } = doc;
  return [
    `robot ${doc.deviceId} calibrated`,
    `  straight line: measured ${straight.measuredCm} cm, the old geometry said ${straight.predictedCm.toFixed(1)} cm`,
    `  full turn:     measured ${turn.measuredDeg} degrees, the old geometry said ${turn.predictedDeg.toFixed(1)} degrees`,
    `  wheel diameter ${cm(before.wheelDiameterCm)} -> ${cm(after.wheelDiameterCm)}`,
    `  wheel base     ${cm(before.wheelBaseCm)} -> ${cm(after.wheelBaseCm)}`,
    '  sent to the robot (set_config): it uses them now',
    doc.file === undefined
      ? '  not saved (--no-save): the robot forgets them when it restarts'
      : `  saved to ${doc.file}: hal sends them to this robot after every hello`,
  ].join('\n');
}

export const registerCalibrate: RegisterCommand = (program, { io, global }) => {
  const command = new Command('wheels')
    .description(
      "measure a physical robot's wheel diameter and wheel base: it drives a straight line and a full turn, you measure them (the default)",
    )
    .addOption(
      new Option('--distance-cm <cm>', 'the straight line to drive')
        .argParser(distanceArg)
        .default(100),
    )
    .addOption(
      new Option(
        '--measured-distance-cm <cm>',
        'the distance it travels, measured (for scripts; else asked)',
      ).argParser(positiveArg('--measured-distance-cm')),
    )
    .addOption(
      new Option(
        '--measured-turn-deg <degrees>',
        `the angle its ${TURN_DEG}-degree turn turns, measured (for scripts; else asked)`,
      ).argParser(positiveArg('--measured-turn-deg')),
    )
    .addOption(
      new Option(
        '--calibration-dir <dir>',
        'where calibration files are kept (default $HAL_CALIBRATION_DIR, else $XDG_CONFIG_HOME/hal/calibration, else ~/.config/hal/calibration)',
      ),
    )
    .addOption(new Option('--no-save', 'send the values to the robot only; write no file'))
    .addOption(
      new Option('--answer-timeout <s>', 'give up when a question is not answered within this')
        .argParser(positiveArg('--answer-timeout'))
        .default(600),
    );
  const kinds = ['udp', 'serial'] as const;
  addTargetOptions(command, kinds, { calibration: false }).action(
    async (options: CalibrateOptions) => {
      const target = resolveTarget(options, io.env, kinds);
      const json = global().json;
      const interactive =
        options.measuredDistanceCm === undefined || options.measuredTurnDeg === undefined;
      if (interactive && (json || !canPrompt(io))) {
        throw new CliError(
          'USAGE',
          'give --measured-distance-cm and --measured-turn-deg, or run hal calibrate in a terminal to be asked',
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
          async ({ hal, deviceId }) => {
            if (!(hal instanceof PhysicalHAL)) {
              throw new HalError('NOT_IMPLEMENTED', 'hal calibrate needs a physical robot');
            }
            // before any motion: an id that cannot name the file would lose the measurement
            const path = options.save ? calibrationPath(dir, deviceId) : undefined;
            progress(io, { json }, `calibrating robot ${deviceId}`);
            const run = await runCalibration(
              hal,
              {
                distanceCm: options.distanceCm,
                ...(options.measuredDistanceCm === undefined
                  ? {}
                  : { measuredDistanceCm: options.measuredDistanceCm }),
                ...(options.measuredTurnDeg === undefined
                  ? {}
                  : { measuredTurnDeg: options.measuredTurnDeg }),
                ...(ask === undefined ? {} : { prompter: ask }),
              },
              io,
              { json },
            );
            if (path === undefined) return { deviceId, ...run };
            // the camera's calibration, if the file has one, is kept
            await updateCalibrationFile(path, deviceId, io, json, (old) => ({
              version: 1,
              deviceId,
              ...(old.camera === undefined ? {} : { camera: old.camera }),
              wheelDiameterCm: run.after.wheelDiameterCm,
              wheelBaseCm: run.after.wheelBaseCm,
              calibratedAt: new Date().toISOString(),
              measurements: {
                straightSteps: Math.round((run.straight.leftSteps + run.straight.rightSteps) / 2),
                measuredDistanceCm: run.straight.measuredCm,
                turnSteps: Math.round(
                  (Math.abs(run.turn.leftSteps) + Math.abs(run.turn.rightSteps)) / 2,
                ),
                measuredTurnDeg: run.turn.measuredDeg,
              },
            }));
            return { deviceId, ...run, file: path };
          },
        );
        emit(io, { json }, doc, () => calibrateText(doc));
      } finally {
        ask?.close();
      }
    },
  );
  // `hal calibrate` is `hal calibrate wheels`; `hal calibrate camera` the camera's
  const calibrate = new Command('calibrate')
    .description(
      'measure a physical robot: its wheels (the default: `hal calibrate wheels`) or its camera (`hal calibrate camera`)',
    )
    .addCommand(command, { isDefault: true })
    .addCommand(cameraCalibrateCommand(io, global));
  program.addCommand(calibrate);
};
