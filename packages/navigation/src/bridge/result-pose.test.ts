import { describe, expect, it } from 'vitest';
import type { HALToolResult } from '@hal/types';
import { GoalSeekingProvider } from '../decision/deterministic.js';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';

// Where calls are counted (an eval's budget), the bridge may take the pose after a motion from
// the motion's result rather than asking for it; and a guard's OBSTACLE_AHEAD goes into its map.

/** A fake robot whose moveTo results carry the pose, as both real HALs' do; getPose counted. */
async function reportingHal(): Promise<{ hal: FakeHAL; poseReads: () => number }> {
  const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, rangeSensors: false }));
  const locomotion = hal.locomotion as {
    -readonly [K in keyof typeof hal.locomotion]: (typeof hal.locomotion)[K];
  };
  const moveTo = locomotion.moveTo.bind(locomotion);
  locomotion.moveTo = async (...args) => {
    const result = await moveTo(...args);
    return { ...result, data: { pose: { x: hal.x, y: hal.y, yaw: hal.yaw } } };
  };
  const getPose = locomotion.getPose.bind(locomotion);
  let reads = 0;
  locomotion.getPose = () => {
    reads += 1;
    return getPose();
  };
  return { hal, poseReads: () => reads };
}

describe('NavigationBridge', () => {
  describe('poseFromResults', () => {
    it('takes the pose from each motion result instead of reading it after every motion', async () => {
      const goal = { x: 1, y: 0.6 };
      const counted = await reportingHal();
      const outcome = await new NavigationBridge({
        hal: counted.hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.5,
        poseFromResults: true,
      }).run(goal);
      expect(outcome.status, outcome.message).toBe('reached');
      expect(counted.poseReads()).toBe(1);
      // The poses it took are where the robot was.
      expect(outcome.finalPose?.x).toBeCloseTo(counted.hal.x, 9);
      expect(outcome.finalPose?.y).toBeCloseTo(counted.hal.y, 9);

      const plain = await reportingHal();
      const again = await new NavigationBridge({
        hal: plain.hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.5,
      }).run(goal);
      expect(again.status).toBe('reached');
      expect(plain.poseReads()).toBe(again.cycles + 1);
    });

    it('reads the pose when a motion result carries none or the motion failed', async () => {
      const counted = await reportingHal();
      let failures = 1;
      counted.hal.fault = (call) =>
        call.name === 'moveTo' && failures-- > 0
          ? {
              success: false,
              code: 'HARDWARE_ERROR',
              error: 'slipped',
              timestamp: 0,
              mode: 'simulation',
            }
          : undefined;
      const outcome = await new NavigationBridge({
        hal: counted.hal,
        provider: new GoalSeekingProvider(),
        poseFromResults: true,
      }).run({ x: 0, y: 0 });
      expect(outcome.status).toBe('reached');
      expect(counted.poseReads()).toBe(2);
    });
  });

  describe('a guard between the bridge and the wheels', () => {
    it('maps what the guard saw ahead when it refuses a leg (OBSTACLE_AHEAD), at the distance it gave', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, rangeSensors: false }));
      const refusal: HALToolResult = {
        success: false,
        code: 'OBSTACLE_AHEAD',
        error: 'moveTo: refused, nothing moved: an obstacle 0.3 m ahead',
        details: { distanceM: 0.3 },
        timestamp: 0,
        mode: 'simulation',
      };
      let refused = false;
      hal.fault = (call) => {
        if (call.name !== 'moveTo' || refused) return undefined;
        refused = true;
        return refusal;
      };
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxCycles: 1,
      });
      await bridge.run({ x: 1, y: 0 });
      // 0.07 (the body) + 0.3 ahead of where it stood, toward the leg
      expect(bridge.grid.stateAt(-1 + 0.07 + 0.3 + 0.025, 0)).toBe('occupied');
      expect(bridge.grid.stateAt(-1 + 0.2, 0)).not.toBe('occupied');
    });
  });
});
