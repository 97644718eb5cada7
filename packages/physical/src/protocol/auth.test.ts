import { describe, expect, it } from 'vitest';
import { createAuthenticator, splitMac } from './auth.js';
import { MessageCodec } from './codec.js';

const bytes = (text: string) => new TextEncoder().encode(text);

/** The MAC with one hex digit changed at `index` (to another lowercase hex digit). */
function flipDigit(mac: string, index: number): string {
  const digit = mac[index] === '0' ? '1' : '0';
  return mac.slice(0, index) + digit + mac.slice(index + 1);
}

describe('createAuthenticator', () => {
  it('computes the first 16 bytes of HMAC-SHA256, as the firmware does (RFC 4231 case 2)', async () => {
    const auth = await createAuthenticator(Buffer.from('Jefe').toString('hex'));
    expect(auth.mac(bytes('what do ya want for nothing?'))).toBe(
      '5bdcc146bf60754e6a042426089575c7',
    );
  });

  describe('#verify', () => {
    it('accepts the right MAC and refuses one that differs in any single digit', async () => {
      const auth = await createAuthenticator('000102030405060708090a0b0c0d0e0f');
      const json = bytes('{"seq":7,"sid":9,"ok":true,"cmd":"get_status","running":false}');
      const mac = auth.mac(json);
      expect(auth.verify(json, mac)).toBe(true);
      for (let i = 0; i < mac.length; i++) {
        expect(auth.verify(json, flipDigit(mac, i)), `digit ${i}`).toBe(false);
      }
    });

    it('refuses a MAC of the wrong length or case without throwing', async () => {
      const auth = await createAuthenticator('c0ffee');
      const json = bytes('{"ok":true}');
      const mac = auth.mac(json);
      expect(auth.verify(json, mac.slice(0, 31))).toBe(false);
      expect(auth.verify(json, `${mac}0`)).toBe(false);
      expect(auth.verify(json, '')).toBe(false);
      expect(mac).toMatch(/[a-f]/);
      expect(auth.verify(json, mac.toUpperCase())).toBe(false);
      expect(auth.verify(json, 'é'.repeat(32))).toBe(false);
    });
  });

  it('makes the codec refuse a reply whose MAC differs in any single byte', async () => {
    const auth = await createAuthenticator('00112233');
    const codec = new MessageCodec(auth);
    const signed = codec.encode({ seq: 3, sid: 4, ok: true, cmd: 'heartbeat' });
    expect(codec.decode(signed).ok).toBe(true);
    const split = splitMac(signed)!;
    for (let i = 0; i < split.mac.length; i++) {
      const forged = bytes(`${new TextDecoder().decode(split.json)}#${flipDigit(split.mac, i)}`);
      const result = codec.decode(forged);
      expect(result.ok, `digit ${i}`).toBe(false);
      if (!result.ok) expect(result.error.code).toBe('AUTH_FAILED');
    }
  });
});
