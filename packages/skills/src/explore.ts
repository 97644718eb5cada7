import { GoalSeekingProvider } from '@hal/navigation';
import type { Point } from '@hal/navigation';
import type { ToolResult } from '@hal/tools';
import { bridgeFor } from './camera-bridge.js';
import { mostPromisingFrontier } from './frontier-choice.js';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import { describeThings, seenFrom } from './seen-thing.js';
import { m2, motionFailure, skillResult } from './skill-result.js';

/** Cycles one `explore` may drive toward its frontier. */
const EXPLORE_CYCLES = 6;
/** This near the frontier, the robot is there, metres. */
const THERE_M = 0.3;

/**
 * `explore`: one step into what the camera has not seen: looks, picks the most promising
 * frontier of the map it has built (most unknown floor in view of it per metre driven), drives
 * there in legs (looking after each), and says what it saw that it had not seen before.
 */
export async function exploreSkill(
  ctx: SkillContext,
  tried: Point[],
  signal?: AbortSignal,
): Promise<ToolResult> {
  const since = Date.now();
  const known = new Set(ctx.memory.all().map((o) => o.id));
  await ctx.perception.look();
  const pose = await ctx.pose();
  const frontier = mostPromisingFrontier(ctx.grid, pose, { exclude: tried });
  if (frontier === undefined) {
    return skillResult('not-found', 'Nothing left to explore that I can reach from here.', {
      pose: skillPose(pose),
    });
  }
  tried.push(frontier.target);
  const bridge = bridgeFor(ctx, new GoalSeekingProvider(), THERE_M, EXPLORE_CYCLES);
  const outcome = await bridge.run(frontier.target, signal === undefined ? {} : { signal });
  const after = await ctx.pose();
  const fresh = ctx.memory
    .all()
    .filter((o) => !known.has(o.id) && o.lastSeenAt >= since - 1)
    .map((o) => seenFrom(o, after))
    .sort((a, b) => a.distanceM - b.distanceM);
  const facts = { objects: fresh, pose: skillPose(after) };
  const seen = fresh.length === 0 ? 'nothing new' : describeThings(fresh);
  const toward = `toward (${m2(frontier.target.x)}, ${m2(frontier.target.y)})`;
  if (outcome.reason === 'EMERGENCY_STOPPED')
    return skillResult(
      'estopped',
      `Stopped exploring: the emergency stop is engaged.`,
      facts,
      'EMERGENCY_STOPPED',
    );
  const last = outcome.lastResult;
  if (outcome.status === 'failed' && last !== undefined && !last.success) {
    const failure = motionFailure(last);
    if (failure.outcome === 'refused')
      return skillResult(
        'refused',
        `Explored ${toward} until a motion was refused: ${failure.why}. New: ${seen}.`,
        facts,
        failure.code,
      );
    if (failure.outcome === 'failed')
      return skillResult(
        'failed',
        `Explored ${toward} until a motion failed (${failure.code}): ${failure.why}. New: ${seen}.`,
        facts,
        failure.code,
      );
  }
  return skillResult('done', `Explored ${toward}. New: ${seen}.`, facts);
}
