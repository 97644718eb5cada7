import type { WorldObserver } from '@hal/navigation';
import { integrateFreeSpace } from './grid-fusion.js';
import type { Look, Perception } from './perception.js';

/** Options of {@link perceivingObserver}. */
export interface PerceivingObserverOptions {
  /** Called after each frame is perceived (for recording and live views). */
  onLook?: (look: Look) => void;
  /**
   * The time a frame counts as taken at, ms (the memory's "last seen"). Default `Date.now`; a
   * counter makes runs repeatable.
   */
  now?: () => number;
}

/**
 * The navigation bridge's world observer from a {@link Perception}: each cycle's frame is
 * perceived at the cycle's pose, its objects remembered in `perception.memory` and its free space
 * laid into the bridge's grid. The bridge captures the frame and reads the pose, so this makes
 * no HAL call of its own. A cycle with no frame (the camera failed or was slow) is skipped.
 */
export function perceivingObserver(
  perception: Perception,
  options: PerceivingObserverOptions = {},
): WorldObserver {
  const now = options.now ?? Date.now;
  return async ({ frame, pose, grid }) => {
    if (frame === undefined || frame === '') return;
    const capturedAt = now();
    const percept = await perception.perceiver.perceive(frame, pose, capturedAt);
    const remembered = perception.memory.remember(percept.objects, capturedAt);
    integrateFreeSpace(grid, pose, percept.freeSpace);
    options.onLook?.({ ...percept, remembered });
  };
}
