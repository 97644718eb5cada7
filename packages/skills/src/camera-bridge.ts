import { NavigationBridge } from '@hal/navigation';
import type { DecisionProvider } from '@hal/navigation';
import { perceivingObserver } from '@hal/perception';
import type { SkillContext } from './skill-context.js';

/** The navigation bridge over the skill set's robot, map and memory, seeing with the camera. */
export function bridgeFor(
  ctx: SkillContext,
  provider: DecisionProvider,
  goalToleranceM: number,
  maxCycles = ctx.maxCycles,
): NavigationBridge {
  let frames = 0;
  return new NavigationBridge({
    hal: ctx.hal,
    provider,
    grid: ctx.grid,
    // frames are numbered, not timed, so that a run is repeatable
    observe: perceivingObserver(ctx.perception, { now: () => (frames += 1) }),
    // the camera is the sense every robot of ours has (the V1 cube has no range sensors)
    rangeSensors: false,
    maxLegM: ctx.legM(),
    // a leg more than this off the heading is looked at first (the camera sees 62 degrees)
    faceBeforeDrivingDeg: 45,
    goalToleranceM,
    maxCycles,
    poseFromResults: true,
  });
}
