import { angleDifference, normalizeAngle } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import { decision, ScriptedProvider } from './scripted-provider.fixture.js';

// Carrying out decisions: STOP judged from the actual pose, ROTATE_TO to an absolute heading.

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('stops when the provider says STOP away from the goal, even claiming it was reached', async () => {
      const hal = await ready(new FakeHAL());
      const provider = new ScriptedProvider([decision({ type: 'STOP' }, true)]);
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(outcome.status).toBe('stopped');
      expect(outcome.reason).toBe('PROVIDER_STOPPED');
      expect(outcome.message).toContain('claimed');
    });
  });

  describe('ROTATE_TO', () => {
    // yaw_deg is an absolute heading, degrees, counter-clockwise from +x (REP-103); the bridge
    // turns the shorter way. Positive is NOT a relative turn to the right.
    it.each([
      { from: 0, to: 90, direction: 'left', degrees: 90 },
      { from: 90, to: 0, direction: 'right', degrees: 90 },
      { from: 0, to: -45, direction: 'right', degrees: 45 },
      { from: 170, to: -170, direction: 'left', degrees: 20 },
      { from: 30, to: 30 + 360, direction: undefined, degrees: 0 },
    ])('turns from $from deg to the absolute heading $to deg: $direction $degrees', async (c) => {
      const hal = await ready(
        new FakeHAL({ start: { x: 0, y: 0, yaw: (c.from * Math.PI) / 180 } }),
      );
      const provider = new ScriptedProvider([
        decision({ type: 'ROTATE_TO', yaw_deg: c.to }),
        decision({ type: 'STOP' }),
      ]);
      await new NavigationBridge({ hal, provider }).run({ x: 1, y: 1 });
      const rotations = hal.calls.filter((call) => call.name === 'rotate');
      if (c.direction === undefined) {
        expect(rotations).toHaveLength(0);
      } else {
        expect(rotations).toHaveLength(1);
        expect(rotations[0]?.args[0]).toBe(c.direction);
        expect(rotations[0]?.args[1] as number).toBeCloseTo(c.degrees, 6);
      }
      const target = normalizeAngle((c.to * Math.PI) / 180);
      expect(Math.abs(angleDifference(hal.yaw, target))).toBeLessThan((0.5 * Math.PI) / 180);
    });
  });
});
