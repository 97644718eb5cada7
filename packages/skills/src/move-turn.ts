import type { ToolResult } from '@hal/tools';
import type { HALToolResult } from '@hal/types';
import type { SkillContext } from './skill-context.js';
import { skillPose } from './skill-context.js';
import {
  badArguments,
  deg0,
  interruptedResult,
  m2,
  motionFailure,
  skillResult,
} from './skill-result.js';
import { wrapDeg } from './seen-thing.js';

/**
 * The longest leg a refusal allows, cm: the robot's own limit on one call ("must be at most 150")
 * or the leash's ("at most 0.5 m per call"). Undefined for any other refusal.
 */
export function legLimitCm(code: string, why: string): number | undefined {
  if (code === 'RANGE_EXCEEDED') {
    const m = /"distanceCm" must be at most (\d+(?:\.\d+)?)/.exec(why);
    return m === null ? undefined : Number(m[1]);
  }
  if (code === 'LEASH_DISTANCE') {
    const m = /at most (\d+(?:\.\d+)?) m per call/.exec(why);
    return m === null ? undefined : Number(m[1]) * 100;
  }
  return undefined;
}

/**
 * `move`: straight ahead (cm > 0) or back (cm < 0), under the leash and the guard. A distance
 * longer than one call may drive (the robot's limit or the leash's) is driven in legs each call
 * allows, and the answer says so.
 */
export async function moveSkill(ctx: SkillContext, cm: number): Promise<ToolResult> {
  if (cm === 0) return badArguments('move', '"cm" must not be 0');
  const before = await ctx.pose();
  const sign = Math.sign(cm);
  let left = Math.abs(cm);
  let leg = left;
  let legs = 0;
  let result: HALToolResult | undefined;
  let limitWords: string | undefined;
  let limitCm = 0;
  while (left > 0.05) {
    if (legs > 0 && ctx.interrupted())
      return interruptedResult('move', { pose: skillPose(await ctx.pose()) });
    const step = Math.min(leg, left);
    result =
      sign > 0
        ? await ctx.hal.locomotion.moveForward(step)
        : await ctx.hal.locomotion.moveBackward(step);
    if (result.success) {
      legs += 1;
      left -= step;
      continue;
    }
    const failure = motionFailure(result);
    const limit = failure.outcome === 'refused' ? legLimitCm(failure.code, failure.why) : undefined;
    // a refusal moves nothing: drive the same distance in legs the limit allows (once)
    if (limit === undefined || limit <= 0.5 || limitWords !== undefined) break;
    limitCm = limit;
    leg = Math.floor(limit * 0.98 * 10) / 10;
    limitWords = failure.code === 'LEASH_DISTANCE' ? 'the leash' : 'the robot';
  }
  const after = await ctx.pose();
  // along the heading it started with: what the robot drove, forward positive
  const movedCm =
    Math.round(
      ((after.x - before.x) * Math.cos(before.yaw) + (after.y - before.y) * Math.sin(before.yaw)) *
        1000,
    ) / 10;
  const facts = { movedCm, pose: skillPose(after), ...(legs > 1 ? { legs } : {}) };
  const way = cm > 0 ? 'forward' : 'backward';
  const inLegs =
    limitWords === undefined || legs < 2
      ? ''
      : ` in ${legs} legs (${limitWords} allows at most ${limitCm.toFixed(0)} cm per motion)`;
  if (result === undefined || result.success) {
    return skillResult('done', `Moved ${Math.abs(movedCm).toFixed(1)} cm ${way}${inLegs}.`, facts);
  }
  const failure = motionFailure(result);
  const moved = `moved ${Math.abs(movedCm).toFixed(1)} cm${inLegs}`;
  switch (failure.outcome) {
    case 'guard-stopped':
      return skillResult(
        'guard-stopped',
        `Stopped by the guard: something is ahead, ${m2(aheadM(result.details) ?? 0)} m from the front; ${moved}.`,
        facts,
      );
    case 'refused':
      return skillResult(
        'refused',
        `Refused${movedCm === 0 ? ', nothing moved' : ` after I ${moved}`}: ${failure.why}.`,
        facts,
        failure.code,
      );
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
