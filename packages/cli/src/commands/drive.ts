// `hal drive <action>`: one motion or safety call on one robot, its result printed (and live
// pose on stderr while a motion runs). Numbers are checked before connecting.
import { Command, Option } from 'commander';
import { HalError, isHalError } from '@hal/types';
import { actionText, checkAction } from '../drive/actions.js';
import type { DriveAction } from '../drive/actions.js';
import { runDrive } from '../drive/run-drive.js';
import type { DriveOutcome } from '../drive/run-drive.js';
import { addGuardOptions, guardFromOptions } from '../guard-options.js';
import type { GuardCliOptions } from '../guard-options.js';
import { emit } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { poseText } from '../pose-text.js';
import { addTargetOptions, resolveTarget, targetArgs } from '../target.js';
import type { Target, TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import { angleArg, distanceArg, numberArg, QUANTITY_FORMS } from '../values.js';
import type { RegisterCommand } from './context.js';

function outcomeText(action: DriveAction, { result, pose, stoppedByUser }: DriveOutcome): string {
  const time =
    result.executionTime === undefined ? '' : ` in ${(result.executionTime / 1000).toFixed(2)} s`;
  const stopped = stoppedByUser ? ', stopped on Ctrl-C' : '';
  return `${actionText(action)}: ok${time} (${result.mode}${stopped})\npose ${poseText(pose)}`;
}

/**
 * An EMERGENCY_STOPPED error in the terms of the command line: the action as typed (not the HAL
 * method), and the command that resets the latch in place of the library's
 * `safety.resetEmergencyStop()`.
 */
function latchedError(error: HalError, action: DriveAction, target: Target): HalError {
  const message = error.message
    .replace(/^[a-zA-Z]+: /, '')
    .replace(/;? *call safety\.resetEmergencyStop\(\) first/, '');
  const args = targetArgs(target);
  const hint = args === undefined ? '' : `; reset it with: hal drive reset-estop ${args}`;
  return new HalError('EMERGENCY_STOPPED', `${actionText(action)}: ${message}${hint}`, {
    cause: error,
    ...(error.details === undefined ? {} : { details: error.details }),
  });
}

/** Calls any client may make (a WebSocket watcher too): they never wait for control. */
const SAFETY_ONLY: ReadonlySet<DriveAction['kind']> = new Set(['stop', 'estop']);

async function drive(
  command: Command,
  action: DriveAction,
  io: CliIO,
  global: GlobalOptions,
): Promise<void> {
  checkAction(action);
  const options = command.optsWithGlobals<TargetCliOptions & GuardCliOptions>();
  const target = resolveTarget(options, io.env);
  const connect =
    options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
  const outcome = await withTarget(
    target,
    io,
    { ...connect, json: global.json, role: SAFETY_ONLY.has(action.kind) ? 'safety' : 'control' },
    ({ hal }) =>
      runDrive(guardFromOptions(hal, options, io, global.json, target).hal, action, io, global),
  ).catch((error: unknown) => {
    if (isHalError(error) && error.code === 'EMERGENCY_STOPPED') {
      throw latchedError(error, action, target);
    }
    throw error;
  });
  emit(io, global, { action, ...outcome }, () => outcomeText(action, outcome));
}

export const registerDrive: RegisterCommand = (program, { io, global }) => {
  const parent = new Command('drive').description(
    'move a robot, stop it, or latch and reset its emergency stop',
  );
  addTargetOptions(parent);
  addGuardOptions(parent);
  const sub = (name: string, description: string) =>
    parent.command(name).description(description).allowExcessArguments(false);
  const run = (command: Command, action: DriveAction) => drive(command, action, io, global());

  sub('forward', 'drive straight, negative to reverse')
    .argument('<distance>', QUANTITY_FORMS.distance, distanceArg('distance'))
    .action((metres: number, _o: unknown, c: Command) => run(c, { kind: 'forward', metres }));
  sub('turn', 'turn in place, positive counter-clockwise (left)')
    .argument('<angle>', QUANTITY_FORMS.angle, angleArg('angle'))
    .action((degrees: number, _o: unknown, c: Command) => run(c, { kind: 'turn', degrees }));
  sub('move-to', 'turn toward a point and drive to it (REP-103: x forward, y left of the start)')
    .argument('<x>', QUANTITY_FORMS.distance, distanceArg('x'))
    .argument('<y>', QUANTITY_FORMS.distance, distanceArg('y'))
    .addOption(
      new Option('--speed <m/s>', 'cruise speed, m/s').argParser(numberArg('--speed', {}, 'm/s')),
    )
    .action((x: number, y: number, o: { speed?: number }, c: Command) =>
      run(c, { kind: 'move-to', x, y, ...(o.speed === undefined ? {} : { speed: o.speed }) }),
    );
  sub('wheels', 'drive the wheels at powers -255..255 (without --duration: until Ctrl-C)')
    .argument('<left>', 'left wheel power', numberArg('left'))
    .argument('<right>', 'right wheel power', numberArg('right'))
    .addOption(
      new Option('--duration <ms>', 'stop after this long, ms').argParser(
        numberArg('--duration', {}, 'ms'),
      ),
    )
    .action((left: number, right: number, o: { duration?: number }, c: Command) =>
      run(c, {
        kind: 'wheels',
        left,
        right,
        ...(o.duration === undefined ? {} : { durationMs: o.duration }),
      }),
    );
  sub('stop', 'stop the wheels now').action((_o: unknown, c: Command) => run(c, { kind: 'stop' }));
  sub('estop', 'latch the emergency stop (until reset-estop)')
    .argument('[reason]', 'why, kept with the latch')
    .action((reason: string | undefined, _o: unknown, c: Command) =>
      run(c, { kind: 'estop', ...(reason === undefined ? {} : { reason }) }),
    );
  sub('reset-estop', 'reset the emergency stop').action((_o: unknown, c: Command) =>
    run(c, { kind: 'reset-estop' }),
  );
  program.addCommand(parent);
};
