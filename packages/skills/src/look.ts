import type { Pose2D } from '@hal/navigation';
import { clearanceAhead } from '@hal/perception';
import type { FreeSpaceColumn, Look } from '@hal/perception';
import type { ToolResult } from '@hal/tools';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import { describeThings, seenFrom } from './seen-thing.js';
import type { SeenThing } from './seen-thing.js';
import { interruptedResult, m2, motionFailure, skillResult } from './skill-result.js';

/** How far the floor is free, metres from the body's front, as far as the camera saw. */
export interface Clear {
  aheadM: number;
  leftM: number;
  rightM: number;
  /** With `around`: the view behind. */
  behindM?: number;
}

/** A column this far off the heading counts as left or right of the view, radians. */
const SIDE_RAD = (10 * Math.PI) / 180;
/** Half the corridor the body sweeps driving ahead, metres (the V1 is 0.14 m wide, plus margin). */
const CORRIDOR_HALF_M = 0.1;
/** The turn between two views when looking round, degrees (the camera sees 62 across). */
const AROUND_STEP_DEG = 45;

/** Free floor ahead (the body's corridor) and in the left and right parts of one view. */
export function clearOf(freeSpace: readonly FreeSpaceColumn[], bodyRadiusM: number): Clear {
  const side = (keep: (c: FreeSpaceColumn) => boolean) => {
    let nearest = Number.POSITIVE_INFINITY;
    for (const column of freeSpace) if (keep(column)) nearest = Math.min(nearest, column.distanceM);
    return Number.isFinite(nearest) ? round2(Math.max(0, nearest - bodyRadiusM)) : 0;
  };
  return {
    aheadM: round2(clearanceAhead(freeSpace, bodyRadiusM, CORRIDOR_HALF_M).aheadM),
    leftM: side((c) => c.bearingRad > SIDE_RAD),
    rightM: side((c) => c.bearingRad < -SIDE_RAD),
  };
}

/** The things one look's sightings were remembered as, seen from `pose`, nearest first. */
function thingsOf(looks: readonly Look[], pose: Pose2D): SeenThing[] {
  const byId = new Map(looks.flatMap((l) => l.remembered).map((o) => [o.id, o]));
  return [...byId.values()].map((o) => seenFrom(o, pose)).sort((a, b) => a.distanceM - b.distanceM);
}

function clearWords(clear: Clear): string {
  const behind = clear.behindM === undefined ? '' : `, behind ${m2(clear.behindM)} m`;
  // the side with more clear floor, when the two differ by more than the estimate's error
  const open =
    Math.abs(clear.leftM - clear.rightM) < 0.2
      ? ''
      : ` More open: ${clear.leftM > clear.rightM ? 'left' : 'right'}.`;
  return `Clear floor: ahead ${m2(clear.aheadM)} m, left ${m2(clear.leftM)} m, right ${m2(clear.rightM)} m${behind}.${open}`;
}

/** "2 boxes and 1 pillar": how many of each kind, for a count a small model need not make. */
export function countWords(things: readonly SeenThing[]): string {
  const n = (kind: SeenThing['kind']) => things.filter((t) => t.kind === kind).length;
  const parts: string[] = [];
  const boxes = n('box');
  const pillars = n('pillar');
  const other = n('unknown');
  if (boxes > 0) parts.push(`${boxes} box${boxes === 1 ? '' : 'es'}`);
  if (pillars > 0) parts.push(`${pillars} pillar${pillars === 1 ? '' : 's'}`);
  if (other > 0) parts.push(`${other} other thing${other === 1 ? '' : 's'}`);
  return parts.join(' and ');
}

/**
 * `look`: one frame, what it shows (the objects, nearest first, and how far the floor is clear),
 * remembered and mapped. With `around`, eight views 45° apart, turning a full circle back to the
 * heading it started from; the clearances are then those of the views ahead, left (90°), right
 * and behind.
 */
export async function lookSkill(ctx: SkillContext, around: boolean): Promise<ToolResult> {
  await ctx.pose();
  if (!around) {
    const look = await ctx.perception.look();
    const clear = clearOf(look.freeSpace, ctx.perception.bodyRadiusM);
    const things = thingsOf([look], look.pose);
    const seen =
      things.length === 0 ? 'I see no coloured object.' : `I see ${describeThings(things)}.`;
    return skillResult('done', `${seen} ${clearWords(clear)}`, {
      objects: things,
      clear,
      pose: skillPose(look.pose),
    });
  }
  const looks: Look[] = [];
  const ahead: number[] = [];
  for (let view = 0; view < 360 / AROUND_STEP_DEG; view += 1) {
    if (view > 0) {
      if (ctx.interrupted())
        return interruptedResult('look', { pose: skillPose(await ctx.pose()) });
      const turned = await ctx.hal.locomotion.rotate('left', AROUND_STEP_DEG);
      if (!turned.success) {
        const failure = motionFailure(turned);
        const pose = await ctx.pose();
        const things = thingsOf(looks, pose);
        const seen = things.length === 0 ? '' : ` Seen so far: ${describeThings(things)}.`;
        return skillResult(
          failure.outcome === 'guard-stopped' ? 'failed' : failure.outcome,
          `Could not look all round: the turn failed (${failure.code}): ${failure.why}.${seen}`,
          { objects: things, pose: skillPose(pose) },
          failure.code,
        );
      }
    }
    const look = await ctx.perception.look();
    looks.push(look);
    ahead.push(clearOf(look.freeSpace, ctx.perception.bodyRadiusM).aheadM);
  }
  // back to the heading it started from
  if (ctx.interrupted()) return interruptedResult('look', { pose: skillPose(await ctx.pose()) });
  const back = await ctx.hal.locomotion.rotate('left', AROUND_STEP_DEG);
  const pose = await ctx.pose();
  const quarter = 90 / AROUND_STEP_DEG;
  const clear: Clear = {
    aheadM: ahead[0] ?? 0,
    leftM: ahead[quarter] ?? 0,
    behindM: ahead[2 * quarter] ?? 0,
    rightM: ahead[3 * quarter] ?? 0,
  };
  const things = thingsOf(looks, pose);
  const seen =
    things.length === 0
      ? 'I see no coloured object all round.'
      : `All round I see ${countWords(things)}: ${describeThings(things)}.`;
  const turnedBack = back.success
    ? ''
    : ' The last turn back failed: I may not face the way I did.';
  return skillResult('done', `${seen} ${clearWords(clear)}${turnedBack}`, {
    objects: things,
    clear,
    pose: skillPose(pose),
  });
}

function round2(v: number): number {
  return Math.round(v * 100) / 100;
}
