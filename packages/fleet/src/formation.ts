import { angleDifference, HalError } from '@hal/types';
import type { PlanarPose } from '@hal/types';

/** Where a follower keeps station, metres, in the leader's frame (REP-103: x ahead, y left). */
export interface FormationOffset {
  x: number;
  y: number;
}

/** Named formations: `column` (single file behind), `line` (abreast), `wedge` (a V behind). */
export const FORMATION_SHAPES = ['column', 'line', 'wedge'] as const;
export type FormationShape = (typeof FORMATION_SHAPES)[number];

/** A follower's slot in the world for the leader's pose: the offset turned by the leader's yaw. */
export function slotPosition(
  leader: PlanarPose,
  offset: FormationOffset,
): { x: number; y: number } {
  const c = Math.cos(leader.yaw);
  const s = Math.sin(leader.yaw);
  return { x: leader.x + c * offset.x - s * offset.y, y: leader.y + s * offset.x + c * offset.y };
}

/**
 * Offsets for `followers` in a named shape, `spacingM` apart. Column: 1, 2, 3... spacings
 * behind. Line: beside the leader, alternately left and right. Wedge: alternately left and right,
 * each pair one spacing further back and out.
 */
export function formationOffsets(
  shape: FormationShape,
  followers: readonly string[],
  spacingM: number,
): Record<string, FormationOffset> {
  if (!(FORMATION_SHAPES as readonly string[]).includes(shape)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `formation must be one of ${FORMATION_SHAPES.join(', ')}, got ${JSON.stringify(shape)}`,
      { details: { parameter: 'shape', received: shape } },
    );
  }
  if (typeof spacingM !== 'number' || !Number.isFinite(spacingM) || spacingM <= 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `formation spacing must be a positive number of metres, got ${String(spacingM)}`,
      { details: { parameter: 'spacingM', received: spacingM } },
    );
  }
  const offsets: Record<string, FormationOffset> = {};
  followers.forEach((id, i) => {
    const rank = Math.floor(i / 2) + 1;
    const side = i % 2 === 0 ? 1 : -1;
    if (shape === 'column') offsets[id] = { x: -(i + 1) * spacingM, y: 0 };
    else if (shape === 'line') offsets[id] = { x: 0, y: side * rank * spacingM };
    else offsets[id] = { x: -rank * spacingM, y: side * rank * spacingM };
  });
  return offsets;
}

/** What a follower should do next. */
export type FollowerAction =
  | { kind: 'hold' }
  | { kind: 'moveTo'; x: number; y: number }
  | { kind: 'rotate'; direction: 'left' | 'right'; degrees: number };

/**
 * The follower's next action: drive to its slot when farther than `toleranceM`, else (when
 * `alignHeading`) turn in place to the leader's heading when off by more than
 * `headingToleranceRad`, else hold.
 */
export function decideFollowerAction(input: {
  pose: PlanarPose;
  slot: { x: number; y: number };
  leaderYaw: number;
  toleranceM: number;
  headingToleranceRad: number;
  alignHeading: boolean;
}): FollowerAction {
  const { pose, slot } = input;
  if (Math.hypot(slot.x - pose.x, slot.y - pose.y) > input.toleranceM) {
    return { kind: 'moveTo', x: slot.x, y: slot.y };
  }
  const error = angleDifference(input.leaderYaw, pose.yaw);
  if (input.alignHeading && Math.abs(error) > input.headingToleranceRad) {
    return {
      kind: 'rotate',
      direction: error > 0 ? 'left' : 'right',
      degrees: (Math.abs(error) * 180) / Math.PI,
    };
  }
  return { kind: 'hold' };
}
