import { describe, expect, it } from 'vitest';
import { createAuthenticator } from '../protocol/auth.js';
import { MessageCodec } from '../protocol/codec.js';
import { Refusal } from './refusal.js';
import { MockWire } from './wire.js';

const encode = (text: string) => new TextEncoder().encode(text);

describe('MockWire', () => {
  describe('#read', () => {
    const wire = new MockWire(undefined);

    it('reads a JSON object, unknown fields and all', () => {
      expect(wire.read(encode('{"cmd":"heartbeat","x":{"y":[1]}}'))).toEqual({
        cmd: 'heartbeat',
        x: { y: [1] },
      });
    });

    for (const [what, text] of [
      ['a repeated key', '{"cmd":"stop","cmd":"estop"}'],
      ['a repeated key in a nested object', '{"a":{"b":1,"b":2}}'],
      ['a JSON array', '[1]'],
      ['text that is not JSON', 'stop'],
    ] as const) {
      it(`refuses ${what} as MALFORMED`, () => {
        const read = wire.read(encode(text));
        expect(read instanceof Refusal && read.code).toBe('MALFORMED');
      });
    }
  });

  describe('with a key', () => {
    it('reads what the host codec signs, refuses anything unsigned, and signs its replies', async () => {
      const auth = await createAuthenticator('00112233');
      const codec = new MessageCodec(auth);
      const wire = new MockWire(auth);
      expect(wire.read(codec.encode({ cmd: 'heartbeat', seq: 1, sid: 2 }))).toEqual({
        cmd: 'heartbeat',
        seq: 1,
        sid: 2,
      });
      const unsigned = wire.read(encode('{"cmd":"heartbeat"}'));
      expect(unsigned instanceof Refusal && unsigned.code).toBe('AUTH_FAILED');
      const decoded = codec.decode(wire.reply({ seq: 1, ok: true }));
      expect(decoded.ok).toBe(true);
    });
  });
});
