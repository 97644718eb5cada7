import { describe, expect, it } from 'vitest';
import { GoalSeekingProvider } from '../decision/deterministic.js';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import { decision, ScriptedProvider } from './scripted-provider.fixture.js';

// How HAL results and states end a run: collision, emergency stop, HAL errors.

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('fails with COLLISION when it hits an obstacle it could not know about, and stops the wheels', async () => {
      const box = { minX: 0.4, minY: -0.5, maxX: 0.8, maxY: 0.5 };
      const hal = await ready(
        new FakeHAL({ start: { x: -1, y: 0, yaw: 0 }, boxes: [box], rangeSensors: false }),
      );
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const outcome = await bridge.run({ x: 1.5, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('COLLISION');
      expect(outcome.lastResult?.code).toBe('COLLISION');
      expect(hal.collisions).toBe(1);
      expect(hal.calls.at(-1)?.name).toBe('stop');
      // The world model learned where the obstacle is.
      expect(bridge.grid.stateAt(0.42, 0)).toBe('occupied');
    });

    it('fails with EMERGENCY_STOPPED and moves no more once the emergency stop is latched', async () => {
      const hal = await ready(new FakeHAL({ start: { x: -1.5, y: 0, yaw: 0 } }));
      const bridge = new NavigationBridge({
        hal,
        provider: new GoalSeekingProvider(),
        maxLegM: 0.3,
      });
      let results = 0;
      bridge.on('result', () => {
        results += 1;
        if (results === 2) hal.pressEmergencyStop();
      });
      const outcome = await bridge.run({ x: 1.5, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('EMERGENCY_STOPPED');
      expect(hal.calls.filter((c) => c.name === 'moveTo')).toHaveLength(2);
    });

    it('fails with EMERGENCY_STOPPED when a motion is refused for the emergency stop', async () => {
      const hal = await ready(new FakeHAL());
      hal.fault = () => ({
        success: false,
        code: 'EMERGENCY_STOPPED',
        error: 'latched',
        timestamp: 0,
        mode: 'simulation',
      });
      const bridge = new NavigationBridge({ hal, provider: new GoalSeekingProvider() });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('EMERGENCY_STOPPED');
      expect(outcome.cycles).toBe(1);
    });

    it('reports a failed motion to the provider and fails after three in a row', async () => {
      const hal = await ready(new FakeHAL());
      hal.fault = () => ({
        success: false,
        code: 'HARDWARE_ERROR',
        error: 'motor driver fault',
        timestamp: 0,
        mode: 'simulation',
      });
      const provider = new ScriptedProvider([decision({ type: 'MOVE_TO', x: 1, y: 0 })]);
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(provider.contexts[1]?.lastResult).toEqual({
        action: 'MOVE_TO',
        success: false,
        code: 'HARDWARE_ERROR',
        error: 'motor driver fault',
      });
      expect(outcome.reason).toBe('HAL_ERROR');
      expect(outcome.cycles).toBe(3);
    });

    it('fails with HAL_ERROR at once when the HAL is not initialised', async () => {
      const hal = new FakeHAL();
      const outcome = await new NavigationBridge({ hal, provider: new GoalSeekingProvider() }).run({
        x: 1,
        y: 0,
      });
      expect(outcome.reason).toBe('HAL_ERROR');
      expect(outcome.cycles).toBe(0);
    });
  });
});
