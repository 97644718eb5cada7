// `hal teleop`: drive a robot from the keyboard, with a live pose line. Needs a terminal: the
// terminal is put in raw mode and restored on every way out.
import { Command, Option } from 'commander';
import { integerArg } from '../values.js';
import { HalError } from '@hal/types';
import { addGuardOptions, guardFromOptions } from '../guard-options.js';
import type { GuardCliOptions } from '../guard-options.js';
import { emit, progress } from '../io.js';
import { poseText } from '../pose-text.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import { TELEOP_HELP } from '../teleop/keys.js';
import { runTeleop } from '../teleop/session.js';
import { withStatusLine } from '../teleop/status-line.js';
import { requireTerminal, withRawMode } from '../teleop/terminal.js';
import type { RegisterCommand } from './context.js';

interface TeleopCliOptions extends TargetCliOptions, GuardCliOptions {
  power: number;
  turnPower: number;
}

export const registerTeleop: RegisterCommand = (program, { io, global }) => {
  const command = new Command('teleop')
    .description(`drive a robot from the keyboard: ${TELEOP_HELP}`)
    .addOption(
      new Option('--power <0..255>', 'wheel power driving straight')
        .argParser(integerArg('--power', 1, 255))
        .default(200),
    )
    .addOption(
      new Option('--turn-power <0..255>', 'wheel power turning in place')
        .argParser(integerArg('--turn-power', 1, 255))
        .default(120),
    );
  addGuardOptions(command);
  addTargetOptions(command).action(async (options: TeleopCliOptions) => {
    // refuse before connecting: no robot is touched without a keyboard to stop it
    const stdin = requireTerminal(io);
    const target = resolveTarget(options, io.env);
    const connect =
      options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
    // the HAL's warnings go above the live pose line, never onto it
    const lineIO = withStatusLine(io);
    const summary = await withTarget(
      target,
      lineIO,
      { ...connect, json: global().json },
      ({ hal, deviceId }) => {
        progress(io, global(), `${deviceId} (${hal.mode}): ${TELEOP_HELP}`);
        return withRawMode(stdin, () =>
          runTeleop(
            guardFromOptions(hal, options, lineIO, global().json, target).hal,
            stdin,
            lineIO,
            global(),
            {
              power: options.power,
              turnPower: options.turnPower,
            },
          ),
        );
      },
    );
    emit(
      io,
      global(),
      { event: 'ended', ...summary },
      () => `final pose ${poseText(summary.pose)}`,
    );
    // the robot did not acknowledge the stop: the HAL's error says so, and the exit is non-zero
    if (!summary.stop.stopped) throw new HalError(summary.stop.code, summary.stop.error);
  });
  program.addCommand(command);
};
