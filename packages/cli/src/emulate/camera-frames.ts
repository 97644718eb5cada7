// The emulated ESP32-CAM's pictures: the simulator's software camera, with its default options
// (the robot's own camera), looking from where the emulated body truly is in a world.
import { encodeJpeg, renderRobotView, SimRobot, World } from '@hal/simulation';
import type { WorldMap } from '@hal/simulation';
import type { WorldPose } from './body-pose.js';

/** Renders JPEG frames of `map` from the pose `pose()` gives at each call. */
export interface CameraFrames {
  /** A JPEG of what the camera sees now (the same bytes again while the body has not moved). */
  frame(): Promise<Uint8Array>;
  /** How many frames were rendered (not served again from the last one). */
  readonly rendered: number;
}

/**
 * The camera of a robot at `pose()` in `map` (an empty arena when none is given). The robot is
 * not part of the world (nothing else sees it, and it collides with nothing): the world is only
 * scenery, and the body moves as the emulated robot's wheels say.
 */
export function cameraFrames(pose: () => WorldPose, map?: WorldMap): CameraFrames {
  const world = new World(map === undefined ? {} : { map });
  let last: { key: string; jpeg: Promise<Uint8Array> } | undefined;
  let rendered = 0;
  return {
    frame() {
      const p = pose();
      const key = `${p.x} ${p.y} ${p.yaw}`;
      if (last?.key !== key) {
        rendered += 1;
        const robot = new SimRobot({ id: 'camera', start: p });
        const jpeg = encodeJpeg(renderRobotView(world, robot));
        // a failed encoding is not kept: the next frame tries again
        jpeg.catch(() => {
          if (last?.jpeg === jpeg) last = undefined;
        });
        last = { key, jpeg };
      }
      return last.jpeg;
    },
    get rendered() {
      return rendered;
    },
  };
}
