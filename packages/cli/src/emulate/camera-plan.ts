// What `hal emulate --camera` is asked for, checked before anything starts: the port, the token
// (--camera-token or $HAL_CAMERA_TOKEN), and the world file, read and realised.
import { EvalError, loadWorldFile, realiseWorld } from '@hal/eval';
import type { RealisedWorld } from '@hal/eval';
import { CliError } from '../cli-error.js';
import { cameraToken, CAMERA_TOKEN_ENV } from '../camera-options.js';
import type { EmulateCliOptions } from './emulate-options.js';

/** The camera to serve. */
export interface CameraPlan {
  port: number;
  token?: string;
  /** The world file and what it makes; none: the empty arena. */
  world?: { file: string; realised: RealisedWorld };
}

/**
 * The camera `o` asks for, or undefined without `--camera`. USAGE for --world or --camera-token
 * without --camera, and for a camera on a non-loopback address with neither a token nor
 * --insecure (anyone on that network could watch); FAILED for a world file that cannot be read.
 */
export async function planCamera(
  o: EmulateCliOptions,
  env: Readonly<Record<string, string | undefined>>,
): Promise<CameraPlan | undefined> {
  if (o.camera === undefined) {
    if (o.world !== undefined) throw new CliError('USAGE', '"--world" needs --camera');
    if (o.cameraToken !== undefined) throw new CliError('USAGE', '"--camera-token" needs --camera');
    return undefined;
  }
  const token = cameraToken(o.cameraToken, env);
  if (token === undefined && !o.insecure && !o.bind.startsWith('127.')) {
    throw new CliError(
      'USAGE',
      `refusing to serve the camera on ${o.bind} without a token: anyone who reaches it could watch (give --camera-token or $${CAMERA_TOKEN_ENV}, or --insecure)`,
    );
  }
  let world: CameraPlan['world'];
  if (o.world !== undefined) {
    try {
      world = { file: o.world, realised: realiseWorld(await loadWorldFile(o.world)) };
    } catch (error) {
      if (error instanceof EvalError)
        throw new CliError('FAILED', `${error.code}: ${error.message}`);
      throw error;
    }
  }
  return {
    port: o.camera,
    ...(token === undefined ? {} : { token }),
    ...(world === undefined ? {} : { world }),
  };
}
