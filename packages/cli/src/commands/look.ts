// `hal look`: what the robot sees now, through @hal/perception: each object with its bearing,
// distance, world position (odometry frame), confidence and what is cut off, and how far the floor
// is free per 5 degrees of bearing; `--save` writes the frame annotated. `--world FILE` puts the
// embedded simulator in a world of the eval task format.
import { Command, Option } from 'commander';
import { DEFAULT_FREE_SPACE } from '@hal/perception';
import { emit } from '../io.js';
import { annotateFrame } from '../look/annotate.js';
import { imageFormatOf, writeImage } from '../look/image-file.js';
import { lookDocument } from '../look/look-document.js';
import { cameraOfHal, lookOnce, requireCamera } from '../look/look-once.js';
import { lookText } from '../look/look-text.js';
import { openWorldSimulator, readLookWorld } from '../look/look-world.js';
import type { LookWorld } from '../look/look-world.js';
import { addOverwriteOption, checkOutputPlace } from '../output-place.js';
import { addTargetOptions, describeTarget, resolveTarget } from '../target.js';
import type { Target, TargetCliOptions } from '../target.js';
import { openTarget } from '../target-hal.js';
import type { OpenedHal } from '../target-hal.js';
import { integerArg, usageError } from '../values.js';
import type { RegisterCommand } from './context.js';

interface LookOptions extends TargetCliOptions {
  world?: string;
  save?: string;
  overwrite?: boolean;
  timeout: number;
}

/** How to give a robot of `target`'s kind a camera, for the error of one that has none. */
function cameraHint(target: Target): string {
  switch (target.kind) {
    case 'udp':
    case 'serial':
      return ' (give its ESP32-CAM with --camera-url http://HOST[:PORT])';
    case 'sim':
      return ' (its world says "sensors": { "camera": false })';
    default:
      return ' (the HAL it is served from has none)';
  }
}

export const registerLook: RegisterCommand = (program, { io, global }) => {
  const command = new Command('look')
    .description(
      'what the robot sees now: objects (bearing, distance, world position) and free floor per bearing',
    )
    .addOption(
      new Option(
        '--world <file>',
        'with --sim: the world to look at, in the eval task format ({ map, start, objects })',
      ),
    )
    .addOption(
      new Option(
        '--save <file>',
        'also write the frame with the objects boxed and the free-space boundary drawn (.jpg or .png)',
      ),
    )
    .addOption(
      new Option('--timeout <ms>', 'longest wait for the pose and for a frame')
        .argParser(integerArg('--timeout', 100, 600_000))
        .default(5000),
    );
  addOverwriteOption(command, 'the --save file');
  addTargetOptions(command).action(async (options: LookOptions) => {
    const target = resolveTarget(options, io.env);
    // everything that can be refused is refused before the robot is touched
    let world: LookWorld | undefined;
    if (options.world !== undefined) {
      if (target.kind !== 'sim') throw usageError('"--world" needs --sim');
      if (options.map !== undefined) {
        throw usageError('"--world" and "--map" both name the world: give one');
      }
      world = await readLookWorld(options.world);
    }
    let saveTo: string | undefined;
    if (options.save !== undefined) {
      if (imageFormatOf(options.save) === undefined) {
        throw usageError(`"--save" ${options.save}: name a .jpg, .jpeg or .png file`);
      }
      saveTo = await checkOutputPlace({
        option: '--save',
        path: options.save,
        kind: 'file',
        ...(options.overwrite === true ? { overwrite: true } : {}),
      });
    }
    const connect =
      options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
    const who =
      world === undefined ? describeTarget(target) : `simulator (world ${options.world ?? ''})`;
    const opened: OpenedHal =
      world !== undefined && target.kind === 'sim'
        ? await openWorldSimulator(world, io, {
            speed: target.speed,
            ...(target.calibration === undefined ? {} : { calibration: target.calibration }),
          })
        : await openTarget(target, io, { ...connect, role: 'watch', json: global().json });
    try {
      const { hal, deviceId } = opened;
      requireCamera(hal, `${who} (${deviceId})`, cameraHint(target));
      const camera = cameraOfHal(hal);
      const look = await lookOnce(hal, camera, options.timeout);
      if (saveTo !== undefined) {
        const { projection } = look.perception.perceiver;
        await writeImage(
          saveTo,
          annotateFrame(look.image, look.percept.objects, look.percept.freeSpace, projection),
        );
      }
      const doc = lookDocument({
        robot: who,
        deviceId,
        camera,
        rangeM: DEFAULT_FREE_SPACE.maxRangeM,
        percept: look.percept,
        ...(options.save === undefined ? {} : { saved: options.save }),
      });
      emit(io, global(), doc, () => lookText(doc));
    } finally {
      await opened.close();
    }
  });
  program.addCommand(command);
};
