import { describe, expect, it } from 'vitest';
import { SessionMemory } from './session-memory.js';

const reply = new TextEncoder().encode('{"ok":true}');

describe('SessionMemory', () => {
  describe('#admit', () => {
    it('answers a remembered seq from memory instead of executing it again', () => {
      const memory = new SessionMemory();
      const sid = memory.open(10);
      expect(memory.admit({ cmd: 'heartbeat', seq: 11, sid }, false)).toEqual({
        kind: 'execute',
        remember: true,
        contact: true,
      });
      memory.remember(11, reply);
      expect(memory.admit({ cmd: 'heartbeat', seq: 11, sid }, false)).toEqual({
        kind: 'replay',
        reply,
      });
    });

    it('refuses a seq not above the highest executed one with STALE_SEQUENCE', () => {
      const memory = new SessionMemory();
      const sid = memory.open(10);
      const admission = memory.admit({ cmd: 'heartbeat', seq: 10, sid }, false);
      expect(admission.kind === 'refuse' && admission.refusal.code).toBe('STALE_SEQUENCE');
    });

    it('forgets all but the last 16 replies', () => {
      const memory = new SessionMemory();
      const sid = memory.open(0);
      for (let seq = 1; seq <= 17; seq++) memory.remember(seq, reply);
      expect(memory.admit({ cmd: 'heartbeat', seq: 2, sid }, false).kind).toBe('replay');
      const first = memory.admit({ cmd: 'heartbeat', seq: 1, sid }, false);
      expect(first.kind === 'refuse' && first.refusal.code).toBe('STALE_SEQUENCE');
    });

    it('refuses another session with SESSION_MISMATCH but executes stop whatever its sid', () => {
      const memory = new SessionMemory();
      const sid = memory.open(0);
      const other = memory.admit({ cmd: 'heartbeat', seq: 1, sid: sid + 1 }, false);
      expect(other.kind === 'refuse' && other.refusal.code).toBe('SESSION_MISMATCH');
      expect(memory.admit({ cmd: 'stop', seq: 1, sid: sid + 1 }, false)).toEqual({
        kind: 'execute',
        remember: false,
        contact: false,
      });
    });

    it('executes seed-style requests without a key and refuses them with AUTH_FAILED with one', () => {
      const memory = new SessionMemory();
      const seedStyle = { cmd: 'heartbeat', seq: undefined, sid: undefined };
      expect(memory.admit(seedStyle, false)).toEqual({
        kind: 'execute',
        remember: false,
        contact: true,
      });
      const refused = memory.admit(seedStyle, true);
      expect(refused.kind === 'refuse' && refused.refusal.code).toBe('AUTH_FAILED');
    });
  });

  describe('#helloRetry', () => {
    it('returns the stored reply only for the nonce and seq that opened the session', () => {
      const memory = new SessionMemory();
      memory.open(5);
      memory.openedBy('abc', 5, reply);
      expect(memory.helloRetry('abc', 5)).toBe(reply);
      expect(memory.helloRetry('abc', 6)).toBeUndefined();
      expect(memory.helloRetry(undefined, 5)).toBeUndefined();
      memory.forget();
      expect(memory.helloRetry('abc', 5)).toBeUndefined();
    });
  });
});
