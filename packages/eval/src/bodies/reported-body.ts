import type { HardwareAbstractionLayer } from '@hal/types';
import type { TrialBody } from './trial-body.js';

type Pose2 = { x: number; y: number; yaw: number };

async function readPose(hal: HardwareAbstractionLayer): Promise<Pose2> {
  const p = await hal.locomotion.getPose();
  return { x: p.position.x, y: p.position.y, yaw: p.rotation.yaw };
}

/**
 * A robot seen only through what it reports: its pose is its odometry (`getPose`, read after
 * every call), its clock the wall clock times `timeScale` (an emulator's `--time-scale`). No
 * ground truth: the checks that need one (contacts, what is ahead) cannot run on it.
 */
export async function reportedBody(
  hal: HardwareAbstractionLayer,
  timeScale = 1,
): Promise<TrialBody> {
  let pose = await readPose(hal);
  const started = performance.now();
  return {
    source: 'reported',
    pose: () => ({ ...pose }),
    around: async (run) => {
      const before = pose;
      const result = await run();
      pose = await readPose(hal);
      return { result, pathM: Math.hypot(pose.x - before.x, pose.y - before.y) };
    },
    nowUs: () => (performance.now() - started) * 1000 * timeScale,
    delay: (ms) => new Promise((resolve) => setTimeout(resolve, ms / timeScale)),
    emergencyStopped: () => hal.safety.isEmergencyStopped(),
  };
}
