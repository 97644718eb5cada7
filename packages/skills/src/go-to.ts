import { GoalSeekingProvider } from '@hal/navigation';
import type { NavigationOutcome, Point } from '@hal/navigation';
import { bridgeFor } from './camera-bridge.js';
import type { ToolResult } from '@hal/tools';
import { legLimitCm } from './move-turn.js';
import { ObjectSeekingProvider } from './object-seeker.js';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import { seenFrom } from './seen-thing.js';
import { badArguments, m2, motionFailure, skillResult } from './skill-result.js';
import { TARGET_HELP, targetOf } from './target.js';

/** How near an object `go_to` stops by default, metres from its surface. */
const OBJECT_WITHIN_M = 0.25;

/**
 * Runs a drive; when the leash refused a leg as too long, runs it again (once) with legs it
 * allows: each leg is still one motion within the leash.
 */
async function runLearningLeash(
  ctx: SkillContext,
  drive: () => Promise<NavigationOutcome>,
): Promise<NavigationOutcome> {
  const outcome = await drive();
  const last = outcome.lastResult;
  if (last === undefined || last.success) return outcome;
  const failure = motionFailure(last);
  const limitCm =
    failure.code === 'LEASH_DISTANCE' ? legLimitCm(failure.code, failure.why) : undefined;
  if (limitCm === undefined || limitCm < 5 || ctx.leashLegM !== undefined) return outcome;
  ctx.leashLegM = (limitCm * 0.95) / 100;
  return drive();
}

/** A run that did not arrive, in a skill's words: what stopped it. */
function notArrived(
  outcome: NavigationOutcome,
  where: string,
  facts: Record<string, unknown>,
): ToolResult {
  const last = outcome.lastResult;
  if (outcome.reason === 'EMERGENCY_STOPPED')
    return skillResult(
      'estopped',
      `Stopped on the way to ${where}: the emergency stop is engaged.`,
      facts,
      'EMERGENCY_STOPPED',
    );
  if (last !== undefined && !last.success) {
    const failure = motionFailure(last);
    if (failure.outcome === 'refused')
      return skillResult(
        'refused',
        `Could not go on to ${where}: a motion was refused: ${failure.why}.`,
        facts,
        failure.code,
      );
    if (failure.outcome === 'guard-stopped' && outcome.reason !== 'UNREACHABLE')
      return skillResult(
        'guard-stopped',
        `Stopped by the guard on the way to ${where}: ${failure.why}.`,
        facts,
      );
  }
  switch (outcome.reason) {
    case 'COLLISION':
      return skillResult(
        'blocked',
        `Blocked on the way to ${where}: the robot hit something.`,
        facts,
      );
    case 'UNREACHABLE':
    case 'STUCK':
      return skillResult(
        'blocked',
        `Blocked: I found no way to ${where} on what I have seen (${outcome.message}).`,
        facts,
      );
    case 'STOP_REQUESTED':
      return skillResult(
        'failed',
        `Stopped before reaching ${where}: the run was stopped.`,
        facts,
        'INTERRUPTED',
      );
    default: {
      const code = last?.code ?? outcome.reason;
      return skillResult(
        'failed',
        `Did not reach ${where} (${outcome.reason}): ${outcome.message}.`,
        facts,
        code,
      );
    }
  }
}

/**
 * `go_to` a named thing: finds it (looks round, then explores what the camera maps) unless the
 * memory knows it, then drives in legs on the map the camera builds, looking after each and
 * re-planning, and stops `withinM` (default 0.25 m) from its surface, before it.
 */
export async function goToThing(
  ctx: SkillContext,
  target: string,
  withinM: number | undefined,
  signal?: AbortSignal,
): Promise<ToolResult> {
  const named = targetOf(target);
  if (named === undefined) return badArguments('go_to', TARGET_HELP);
  const within = withinM ?? OBJECT_WITHIN_M;
  // a first look: it fails at once, and says why, on a robot that cannot see
  await ctx.perception.look();
  const provider = new ObjectSeekingProvider({
    target: { ...named, withinM: within },
    memory: ctx.memory,
    standOffM: Math.min(ctx.standOffM, within * 0.7),
  });
  await ctx.pose();
  const outcome = await runLearningLeash(ctx, () =>
    bridgeFor(ctx, provider, 0.15).run(null, signal === undefined ? {} : { signal }),
  );
  const pose = await ctx.pose();
  const found = provider.found;
  const object = found === undefined ? undefined : seenFrom(found, pose);
  const facts: Record<string, unknown> = {
    pose: skillPose(pose),
    ...(object === undefined ? {} : { object }),
  };
  if (provider.phase === 'arrived' && found !== undefined && object !== undefined) {
    const radius = Math.min(0.25, Math.max(0.05, found.widthM / 2));
    const surface = Math.max(0, object.distanceM - radius);
    return skillResult(
      'reached',
      `Reached the ${found.id}: stopped ${m2(surface)} m from it (as I estimate it).`,
      { ...facts, distanceM: Math.round(surface * 100) / 100 },
    );
  }
  if (provider.phase === 'not-found' && found === undefined) {
    return skillResult(
      'not-found',
      `No ${named.query} found: I looked round and explored everything I could reach.`,
      facts,
    );
  }
  const where = found === undefined ? `the ${named.query}` : `the ${found.id}`;
  if (provider.phase === 'not-found')
    return skillResult(
      'blocked',
      `Could not get nearer to ${where}: ${m2(object?.distanceM ?? 0)} m from its centre.`,
      facts,
    );
  return notArrived(outcome, where, facts);
}

/** `go_to` a point (odometry frame, metres), or `go_back`: the same on the map the camera builds. */
export async function goToPoint(
  ctx: SkillContext,
  point: Point,
  toleranceM: number,
  label: string,
  signal?: AbortSignal,
): Promise<ToolResult> {
  await ctx.pose();
  const outcome = await runLearningLeash(ctx, () =>
    bridgeFor(ctx, new GoalSeekingProvider(), toleranceM).run(
      point,
      signal === undefined ? {} : { signal },
    ),
  );
  const pose = await ctx.pose();
  const away = Math.hypot(pose.x - point.x, pose.y - point.y);
  const facts = { pose: skillPose(pose), distanceM: Math.round(away * 100) / 100 };
  if (outcome.status === 'reached')
    return skillResult(
      'reached',
      `Reached ${label}: ${(away * 100).toFixed(1)} cm from it.`,
      facts,
    );
  return notArrived(outcome, label, facts);
}

/** `go_back`: to where the run started (the first pose a skill read). */
export async function goBackSkill(ctx: SkillContext, signal?: AbortSignal): Promise<ToolResult> {
  const start = await ctx.start();
  return goToPoint(
    ctx,
    { x: start.x, y: start.y },
    ctx.pointToleranceM,
    `where I started (${m2(start.x)}, ${m2(start.y)})`,
    signal,
  );
}
