import type { RememberedObject } from '@hal/perception';
import type { ToolResult } from '@hal/tools';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import { describeThing, seenFrom } from './seen-thing.js';
import { badArguments, interruptedResult, motionFailure, skillResult } from './skill-result.js';
import { TARGET_HELP, targetOf } from './target.js';

/** The turn between two looks while searching, degrees (the camera sees 62 across). */
const FIND_STEP_DEG = 60;
/** A bearing under this is already faced, degrees. */
const FACED_DEG = 2;

/** The remembered objects that fit `query` among those `ids` name (what a look just saw). */
function among(ctx: SkillContext, query: string, ids: ReadonlySet<string>): RememberedObject[] {
  return ctx.memory.find(query).filter((o) => ids.has(o.id));
}

/** Turns on the spot by `deg` (left positive); the motion's failure in words, if it failed. */
async function turnBy(ctx: SkillContext, deg: number) {
  if (Math.abs(deg) < FACED_DEG) return undefined;
  const result = await ctx.hal.locomotion.rotate(deg > 0 ? 'left' : 'right', Math.abs(deg));
  return result.success ? undefined : motionFailure(result);
}

/**
 * `find`: looks for the named thing where the robot stands, turning 60° at a time up to a full
 * circle, and turns to face it when it sees it. Not seen: says so, and where the memory last
 * placed one, if anywhere.
 */
export async function findSkill(ctx: SkillContext, target: string): Promise<ToolResult> {
  const named = targetOf(target);
  if (named === undefined) return badArguments('find', TARGET_HELP);
  await ctx.pose();
  for (let view = 0; view < 360 / FIND_STEP_DEG; view += 1) {
    if (view > 0) {
      if (ctx.interrupted())
        return interruptedResult('find', { pose: skillPose(await ctx.pose()) });
      const failure = await turnBy(ctx, FIND_STEP_DEG);
      if (failure !== undefined) {
        const pose = await ctx.pose();
        return skillResult(
          failure.outcome === 'guard-stopped' ? 'failed' : failure.outcome,
          `Stopped looking for the ${named.query}: the turn failed (${failure.code}): ${failure.why}.`,
          { pose: skillPose(pose) },
          failure.code,
        );
      }
    }
    const look = await ctx.perception.look();
    const ids = new Set(look.remembered.map((o) => o.id));
    const match = among(ctx, named.query, ids)[0];
    if (match === undefined) continue;
    const facing = seenFrom(match, look.pose);
    const failure = await turnBy(ctx, facing.bearingDeg);
    const pose = await ctx.pose();
    const object = seenFrom(match, pose);
    const faced = failure === undefined ? ' I turned to face it.' : '';
    return skillResult('found', `Found ${describeThing(object)}.${faced}`, {
      object,
      pose: skillPose(pose),
    });
  }
  const pose = await ctx.pose();
  const earlier = ctx.memory.find(named.query)[0];
  const remembered = earlier === undefined ? undefined : seenFrom(earlier, pose);
  const memory =
    remembered === undefined
      ? ''
      : ` I saw ${describeThing(remembered)} earlier, out of view from here.`;
  return skillResult(
    'not-found',
    `No ${named.query} in view from here (I looked all round).${memory}`,
    { pose: skillPose(pose), ...(remembered === undefined ? {} : { remembered }) },
  );
}

/**
 * `face`: turns on the spot to face the named thing: the one the memory knows best, else one in
 * view now.
 */
export async function faceSkill(ctx: SkillContext, target: string): Promise<ToolResult> {
  const named = targetOf(target);
  if (named === undefined) return badArguments('face', TARGET_HELP);
  let pose = await ctx.pose();
  let known = ctx.memory.find(named.query)[0];
  if (known === undefined) {
    await ctx.perception.look();
    known = ctx.memory.find(named.query)[0];
  }
  if (known === undefined) {
    return skillResult(
      'not-found',
      `I have not seen a ${named.query}; use find or explore first.`,
      {
        pose: skillPose(pose),
      },
    );
  }
  const failure = await turnBy(ctx, seenFrom(known, pose).bearingDeg);
  pose = await ctx.pose();
  if (failure !== undefined) {
    return skillResult(
      failure.outcome === 'guard-stopped' ? 'failed' : failure.outcome,
      `Could not turn to face the ${known.id} (${failure.code}): ${failure.why}.`,
      { pose: skillPose(pose) },
      failure.code,
    );
  }
  return skillResult('done', `Facing the ${known.id}.`, { pose: skillPose(pose) });
}
