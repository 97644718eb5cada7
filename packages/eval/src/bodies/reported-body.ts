import type { HardwareAbstractionLayer } from '@hal/types';
import { delay } from '@hal/types';
import type { TrialBody } from './trial-body.js';

type Pose2 = { x: number; y: number; yaw: number };

async function readPose(hal: HardwareAbstractionLayer): Promise<Pose2> {
  const p = await hal.locomotion.getPose();
  return { x: p.position.x, y: p.position.y, yaw: p.rotation.yaw };
}

/** `p` seen from `origin`: the pose relative to where the trial began. */
function relative(origin: Pose2, p: Pose2): Pose2 {
  const dx = p.x - origin.x;
  const dy = p.y - origin.y;
  const c = Math.cos(origin.yaw);
  const s = Math.sin(origin.yaw);
  const yaw = Math.atan2(Math.sin(p.yaw - origin.yaw), Math.cos(p.yaw - origin.yaw));
  return { x: c * dx + s * dy, y: -s * dx + c * dy, yaw };
}

/**
 * A robot seen only through what it reports: its pose is its odometry (`getPose`, read after
 * every call) relative to the pose it reported when the trial began (the trial's origin: PhysicalHAL
 * starts its odometry there anyway), its clock the wall clock times `timeScale` (an emulator's
 * `--time-scale`). No ground truth: the checks that need one (contacts, what is ahead) cannot run
 * on it.
 */
export async function reportedBody(
  hal: HardwareAbstractionLayer,
  timeScale = 1,
): Promise<TrialBody> {
  const origin = await readPose(hal);
  let pose: Pose2 = { x: 0, y: 0, yaw: 0 };
  const started = performance.now();
  return {
    source: 'reported',
    pose: () => ({ ...pose }),
    around: async (run) => {
      const before = pose;
      const result = await run();
      pose = relative(origin, await readPose(hal));
      return { result, pathM: Math.hypot(pose.x - before.x, pose.y - before.y) };
    },
    nowUs: () => (performance.now() - started) * 1000 * timeScale,
    delay: (ms) => delay(ms / timeScale),
    emergencyStopped: () => hal.safety.isEmergencyStopped(),
  };
}
