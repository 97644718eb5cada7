import type { ToolResult } from '@hal/tools';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import { badArguments, deg0, m2, motionFailure, skillResult } from './skill-result.js';
import { wrapDeg } from './seen-thing.js';

/** `move`: straight ahead (cm > 0) or back (cm < 0), one motion, under the leash and the guard. */
export async function moveSkill(ctx: SkillContext, cm: number): Promise<ToolResult> {
  if (cm === 0) return badArguments('move', '"cm" must not be 0');
  const before = await ctx.pose();
  const result =
    cm > 0 ? await ctx.hal.locomotion.moveForward(cm) : await ctx.hal.locomotion.moveBackward(-cm);
  const after = await ctx.pose();
  // along the heading it started with: what the robot drove, forward positive
  const movedCm =
    Math.round(
      ((after.x - before.x) * Math.cos(before.yaw) + (after.y - before.y) * Math.sin(before.yaw)) *
        1000,
    ) / 10;
  const facts = { movedCm, pose: skillPose(after) };
  const way = cm > 0 ? 'forward' : 'backward';
  if (result.success) {
    return skillResult('done', `Moved ${Math.abs(movedCm).toFixed(1)} cm ${way}.`, facts);
  }
  const failure = motionFailure(result);
  const moved = `moved ${Math.abs(movedCm).toFixed(1)} cm`;
  switch (failure.outcome) {
    case 'guard-stopped':
      return skillResult(
        'guard-stopped',
        `Stopped by the guard: something is ahead, ${m2(aheadM(result.details) ?? 0)} m from the front; ${moved}.`,
        facts,
      );
    case 'refused':
      return skillResult('refused', `Refused, nothing moved: ${failure.why}.`, facts, failure.code);
    case 'estopped':
      return skillResult(
        'estopped',
        `Not moving: the emergency stop is engaged; ${moved}.`,
        facts,
        failure.code,
      );
    case 'blocked':
      return skillResult('blocked', `Blocked: the robot hit something; ${moved}.`, facts);
    default:
      return skillResult(
        'failed',
        `The move failed (${failure.code}): ${failure.why}; ${moved}.`,
        facts,
        failure.code,
      );
  }
}

/** `turn`: on the spot, degrees > 0 to the left (counter-clockwise), < 0 to the right. */
export async function turnSkill(ctx: SkillContext, degrees: number): Promise<ToolResult> {
  if (degrees === 0) return badArguments('turn', '"degrees" must not be 0');
  const before = await ctx.pose();
  const result = await ctx.hal.locomotion.rotate(degrees > 0 ? 'left' : 'right', Math.abs(degrees));
  const after = await ctx.pose();
  let turnedDeg = wrapDeg(((after.yaw - before.yaw) * 180) / Math.PI);
  // a turn of more than half a circle: the wrap hides which way it went
  if (Math.abs(degrees) > 180 && Math.sign(turnedDeg) !== Math.sign(degrees))
    turnedDeg += 360 * Math.sign(degrees);
  turnedDeg = Math.round(turnedDeg * 10) / 10;
  const facts = { turnedDeg, pose: skillPose(after) };
  const way = (d: number) => `${deg0(Math.abs(d))}° ${d > 0 ? 'left' : 'right'}`;
  if (result.success) return skillResult('done', `Turned ${way(turnedDeg)}.`, facts);
  const failure = motionFailure(result);
  if (failure.outcome === 'refused')
    return skillResult('refused', `Refused, nothing moved: ${failure.why}.`, facts, failure.code);
  if (failure.outcome === 'estopped')
    return skillResult(
      'estopped',
      'Not turning: the emergency stop is engaged.',
      facts,
      failure.code,
    );
  return skillResult(
    failure.outcome === 'blocked' ? 'blocked' : 'failed',
    `The turn failed (${failure.code}): ${failure.why}.`,
    facts,
    failure.code,
  );
}

function aheadM(details: Record<string, unknown> | undefined): number | undefined {
  const d = details?.['distanceM'];
  return typeof d === 'number' ? d : undefined;
}
