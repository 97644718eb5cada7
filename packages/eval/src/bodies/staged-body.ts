import { World } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { delay } from '@hal/types';
import type { TaskVariant } from '../variant.js';
import type { TrialBody } from './trial-body.js';

type Pose2 = { x: number; y: number; yaw: number };

/** The body's true pose as it moves, where an emulated robot can tell it (its wheels' steps). */
export interface TruePoseSource {
  /** The true pose now, metres and radians, in the world's frame. */
  truePose(): Pose2;
  /** Calls `listener` with each new true pose; returns what unsubscribes it. */
  onTruePose(listener: (pose: Pose2) => void): () => void;
  /** Resolves (bounded) once the poses of the motion that just ended have all been told. */
  settle(): Promise<void>;
}

/** Longest stretch between two true poses that is checked as one, metres. */
const SWEEP_STEP_M = 0.005;

/**
 * The ground truth of a robot staged in a task's world (an emulated cube whose camera renders the
 * world, its body placed at the variant's start): where the body truly is, from its wheels, and
 * what it touched. The emulated body drives through what it meets, so a contact is judged here:
 * the body's footprint (the simulator's robot's) swept along each stretch between two true poses,
 * one contact counted each time it comes to touch a wall or an object. Its clock is the wall
 * clock times `timeScale`.
 */
export function stagedBody(
  hal: HardwareAbstractionLayer,
  source: TruePoseSource,
  variant: TaskVariant,
  timeScale = 1,
): { body: TrialBody; collisions: () => number; close: () => void } {
  const world = new World({ map: variant.map });
  const robot = world.addRobot({ id: 'judged', start: variant.start });
  const touching = (p: { x: number; y: number }) =>
    world.contactAt(p.x, p.y, robot.radius, robot) !== undefined;
  let last = source.truePose();
  let inContact = touching(last);
  let collisions = 0;
  let pathM = 0;
  const unsubscribe = source.onTruePose((next) => {
    const length = Math.hypot(next.x - last.x, next.y - last.y);
    const pieces = Math.max(1, Math.ceil(length / SWEEP_STEP_M));
    for (let i = 1; i <= pieces; i += 1) {
      const t = i / pieces;
      const now = touching({
        x: last.x + (next.x - last.x) * t,
        y: last.y + (next.y - last.y) * t,
      });
      if (now && !inContact) collisions += 1;
      inContact = now;
    }
    pathM += length;
    last = next;
  });
  const started = performance.now();
  const body: TrialBody = {
    source: 'truth',
    pose: () => ({ ...source.truePose() }),
    around: async (run) => {
      const before = pathM;
      const result = await run();
      await source.settle();
      return { result, pathM: pathM - before };
    },
    nowUs: () => (performance.now() - started) * 1000 * timeScale,
    delay: (ms) => delay(ms / timeScale),
    emergencyStopped: () => hal.safety.isEmergencyStopped(),
  };
  return { body, collisions: () => collisions, close: unsubscribe };
}
