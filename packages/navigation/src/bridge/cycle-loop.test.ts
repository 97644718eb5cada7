import { describe, expect, it } from 'vitest';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import { decision, ScriptedProvider } from './scripted-provider.fixture.js';

// The run's caps: cycles and time.

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('fails with MAX_CYCLES when the cycle cap is reached', async () => {
      const provider = new ScriptedProvider([
        decision({ type: 'ROTATE_TO', yaw_deg: 90 }),
        decision({ type: 'ROTATE_TO', yaw_deg: 0 }),
        decision({ type: 'ROTATE_TO', yaw_deg: 90 }),
        decision({ type: 'ROTATE_TO', yaw_deg: 0 }),
      ]);
      const hal = await ready(new FakeHAL());
      const outcome = await new NavigationBridge({ hal, provider, maxCycles: 4 }).run({
        x: 1,
        y: 0,
      });
      expect(outcome.reason).toBe('MAX_CYCLES');
      expect(outcome.cycles).toBe(4);
    });

    it('fails with TIME_LIMIT when the run takes longer than maxDurationMs', async () => {
      let now = 0;
      const provider = new ScriptedProvider(
        Array.from({ length: 10 }, (_, k) =>
          decision({ type: 'ROTATE_TO', yaw_deg: 90 * (k % 2) + 90 }),
        ),
      );
      const hal = await ready(new FakeHAL());
      hal.fault = () => {
        now += 1000;
        return undefined;
      };
      const bridge = new NavigationBridge({ hal, provider, maxDurationMs: 2500, now: () => now });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('TIME_LIMIT');
    });
  });
});
