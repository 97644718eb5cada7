// The ESP32-CAM's address and token as `hal` takes them: `--camera-url` (an http(s) URL) and
// `--camera-token` (the camera's CAM_TOKEN, default $HAL_CAMERA_TOKEN, so it can stay out of the
// shell's history), for a PhysicalHAL and for the camera `hal emulate --camera` serves.
import { urlArg, usageError } from './values.js';

/** Where the camera's token is read from when no `--camera-token` is given. */
export const CAMERA_TOKEN_ENV = 'HAL_CAMERA_TOKEN';

/** The characters and length the sketch allows a token (cam_http.h IsValidToken). */
const TOKEN = /^[A-Za-z0-9._~-]{1,128}$/;

/** Parses a camera token: 1..128 of A-Z a-z 0-9 - . _ ~, as the camera's sketch allows. */
export function cameraTokenArg(name: string) {
  return (value: string): string => {
    if (!TOKEN.test(value)) {
      throw usageError(`"${name}" must be 1..128 of A-Z a-z 0-9 - . _ ~ (the camera's CAM_TOKEN)`);
    }
    return value;
  };
}

/** Parses the camera's base URL: http:// or https:// (the stream is its `/stream`). */
export const cameraUrlArg: (value: string) => string = urlArg('--camera-url', ['http:', 'https:']);

/**
 * The token to use: `--camera-token` when given, else $HAL_CAMERA_TOKEN (checked, naming the
 * variable), else none.
 */
export function cameraToken(
  given: string | undefined,
  env: Readonly<Record<string, string | undefined>>,
): string | undefined {
  if (given !== undefined) return given;
  const fromEnv = env[CAMERA_TOKEN_ENV];
  return fromEnv === undefined || fromEnv === ''
    ? undefined
    : cameraTokenArg(`$${CAMERA_TOKEN_ENV}`)(fromEnv);
}
