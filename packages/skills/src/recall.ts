import type { ToolResult } from '@hal/tools';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import { countWords } from './look.js';
import { describeThings, seenFrom } from './seen-thing.js';
import { badArguments, skillResult } from './skill-result.js';
import { TARGET_HELP, targetOf } from './target.js';

/** `where_is`: the memory's answer, no motion and no new look: where the named thing was seen. */
export async function whereIsSkill(ctx: SkillContext, target: string): Promise<ToolResult> {
  const named = targetOf(target);
  if (named === undefined) return badArguments('where_is', TARGET_HELP);
  const pose = await ctx.pose();
  const objects = ctx.memory.find(named.query).map((o) => seenFrom(o, pose));
  if (objects.length === 0) {
    return skillResult('not-found', `I have not seen a ${named.query} yet.`, {
      objects,
      pose: skillPose(pose),
    });
  }
  return skillResult('found', `From here, I saw ${describeThings(objects)}.`, {
    objects,
    pose: skillPose(pose),
  });
}

/** `what_have_you_seen`: everything remembered, nearest first, from where the robot is now. */
export async function whatHaveYouSeenSkill(ctx: SkillContext): Promise<ToolResult> {
  const pose = await ctx.pose();
  const objects = ctx.memory
    .all()
    .map((o) => seenFrom(o, pose))
    .sort((a, b) => a.distanceM - b.distanceM);
  const text =
    objects.length === 0
      ? 'I have seen no coloured object yet.'
      : `I have seen ${countWords(objects)}: ${describeThings(objects)}.`;
  return skillResult('done', text, { objects, pose: skillPose(pose) });
}
