import { describe, expect, it } from 'vitest';
import type { DecisionProvider } from '../decision/provider.js';
import { FakeHAL, ready } from './fake-hal.fixture.js';
import { NavigationBridge } from './navigation-bridge.js';
import { decision, ScriptedProvider } from './scripted-provider.fixture.js';

// Asking the provider: no answer, an error, a decision that breaks the schema.

describe('NavigationBridge', () => {
  describe('#run', () => {
    it('fails with PROVIDER_ERROR when the provider never answers, and cancels its signal', async () => {
      let seen: AbortSignal | undefined;
      const provider: DecisionProvider = {
        name: 'silent',
        decide: (_context, signal) => {
          seen = signal;
          return new Promise(() => undefined);
        },
      };
      const hal = await ready(new FakeHAL());
      const bridge = new NavigationBridge({ hal, provider, decisionTimeoutMs: 50 });
      const outcome = await bridge.run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('PROVIDER_ERROR');
      expect(outcome.message).toContain('within 50 ms');
      expect(seen?.aborted).toBe(true);
      expect(hal.calls.filter((c) => c.name !== 'stop')).toHaveLength(0);
    });

    it('fails with PROVIDER_ERROR when the provider throws', async () => {
      const provider: DecisionProvider = {
        name: 'broken',
        decide: () => Promise.reject(new Error('model offline')),
      };
      const hal = await ready(new FakeHAL());
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(outcome.reason).toBe('PROVIDER_ERROR');
      expect(outcome.message).toContain('model offline');
    });

    it('refuses a decision that breaks the schema before anything moves', async () => {
      const provider = new ScriptedProvider([decision({ type: 'MOVE_TO', x: Number.NaN, y: 0 })]);
      const hal = await ready(new FakeHAL());
      const outcome = await new NavigationBridge({ hal, provider }).run({ x: 1, y: 0 });
      expect(outcome.status).toBe('failed');
      expect(outcome.reason).toBe('INVALID_DECISION');
      expect(hal.calls.filter((c) => c.name !== 'stop')).toHaveLength(0);
    });
  });
});
