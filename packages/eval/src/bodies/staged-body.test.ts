import type { HardwareAbstractionLayer } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { builtinTasks } from '../builtin-tasks.js';
import { realiseTask } from '../variant.js';
import { stagedBody } from './staged-body.js';
import type { TruePoseSource } from './staged-body.js';

type Pose2 = { x: number; y: number; yaw: number };

/** A body whose true poses the test tells, one by one. */
function toldPoses(start: Pose2): TruePoseSource & { tell(pose: Pose2): void } {
  let now = start;
  const listeners = new Set<(pose: Pose2) => void>();
  return {
    truePose: () => now,
    onTruePose: (listener) => {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    settle: () => Promise.resolve(),
    tell(pose) {
      now = pose;
      for (const listener of listeners) listener(pose);
    },
  };
}

const hal = { safety: { isEmergencyStopped: () => false } } as unknown as HardwareAbstractionLayer;
// the wall-3m task: the empty 5 m arena, the start facing +x toward its wall (x 2.5 to 2.6 m)
const task = builtinTasks().find((t) => t.id === 'safety/wall-3m');
if (task === undefined) throw new Error('safety/wall-3m is gone');
const variant = realiseTask(task, 1);

describe('stagedBody', () => {
  it('counts one contact for a stretch that crosses into the wall between two poses, not another while it stays', () => {
    const told = toldPoses(variant.start);
    const { body, collisions, close } = stagedBody(hal, told, variant);
    told.tell({ ...variant.start, x: 2.0 });
    expect(collisions()).toBe(0);
    // 2.0 to 2.8 m: the pose before is clear and the pose after is beyond the wall; only the
    // sweep between them finds the contact
    told.tell({ ...variant.start, x: 2.8 });
    told.tell({ ...variant.start, x: 2.9 });
    expect(collisions()).toBe(1);
    expect(body.pose().x).toBe(2.9);
    close();
    told.tell({ ...variant.start, x: 0 });
    told.tell({ ...variant.start, x: 2.9 });
    expect(collisions()).toBe(1);
  });

  it("measures a call's path from the poses told while it ran", async () => {
    const told = toldPoses(variant.start);
    const { body } = stagedBody(hal, told, variant);
    const { result, pathM } = await body.around(() => {
      told.tell({ ...variant.start, x: variant.start.x + 0.3 });
      told.tell({ ...variant.start, x: variant.start.x + 0.5 });
      return Promise.resolve('moved');
    });
    expect(result).toBe('moved');
    expect(pathM).toBeCloseTo(0.5, 9);
    expect(body.source).toBe('truth');
  });
});
