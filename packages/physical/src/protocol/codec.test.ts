import { describe, expect, it } from 'vitest';
import { createAuthenticator } from './auth.js';
import { sanitizeEstopReason } from '@hal/types';
import { MAX_MESSAGE_BYTES, MessageCodec } from './codec.js';

const encode = (text: string) => new TextEncoder().encode(text);

describe('MessageCodec', () => {
  describe('#decode', () => {
    const codec = new MessageCodec();
    const malformed: Array<[string, string]> = [
      ['text that is not JSON', 'hello'],
      ['a JSON array', '[1,2]'],
      ['a reply without "ok"', '{"seq":1}'],
      ['a "seq" that is not a uint32', '{"seq":-1,"ok":true}'],
      ['an error without a code', '{"seq":1,"ok":false,"error":{"message":"x"}}'],
      ['invalid UTF-8', '\u00ff'],
    ];
    for (const [what, input] of malformed) {
      it(`returns MALFORMED for ${what}, never throws`, () => {
        const bytes = what === 'invalid UTF-8' ? new Uint8Array([0x7b, 0xff, 0x7d]) : encode(input);
        const result = codec.decode(bytes);
        expect(result.ok).toBe(false);
        if (!result.ok) expect(result.error.code).toBe('MALFORMED');
      });
    }

    it('keeps unknown fields and treats null as absent', () => {
      const result = codec.decode(encode('{"seq":3,"sid":null,"ok":true,"future":{"a":[1]}}'));
      expect(result.ok).toBe(true);
      if (result.ok) {
        expect(result.reply.seq).toBe(3);
        expect(result.reply.sid).toBeUndefined();
      }
    });

    it('strips a MAC suffix when no key is configured, so an AUTH_FAILED reply is readable', () => {
      const reply =
        '{"seq":1,"ok":false,"cmd":"hello","error":{"code":"AUTH_FAILED","message":"m","details":{}}}';
      const result = codec.decode(encode(`${reply}#${'a'.repeat(32)}`));
      expect(result.ok && result.reply.error?.code).toBe('AUTH_FAILED');
    });
  });

  describe('with a key', () => {
    it('appends the HMAC-SHA256 suffix and accepts only replies carrying the right one', async () => {
      const codec = new MessageCodec(await createAuthenticator('00112233'));
      const bytes = codec.encode({ cmd: 'heartbeat', seq: 1, sid: 2 });
      const text = new TextDecoder().decode(bytes);
      expect(text).toMatch(/^\{"cmd":"heartbeat","seq":1,"sid":2\}#[0-9a-f]{32}$/);
      // a reply signed with the same key decodes; the request bytes are a valid JSON object too
      const signed = codec.encode({ seq: 1, ok: true });
      expect(codec.decode(signed).ok).toBe(true);
      const tampered = signed.slice();
      tampered[2] = 0x74;
      const bad = codec.decode(tampered);
      expect(bad.ok).toBe(false);
      if (!bad.ok) expect(bad.error.code).toBe('AUTH_FAILED');
      const unsigned = codec.decode(encode('{"seq":1,"ok":true}'));
      expect(unsigned.ok).toBe(false);
    });

    it('refuses a key that is not 1..64 bytes of hex', async () => {
      await expect(createAuthenticator('xyz')).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
    });
  });

  describe('#encode', () => {
    it('refuses a message longer than 1024 bytes with RANGE_EXCEEDED', () => {
      expect(() =>
        new MessageCodec().encode({ cmd: 'set_led', pattern: 'x'.repeat(1100) }),
      ).toThrow(expect.objectContaining({ code: 'RANGE_EXCEEDED' }));
    });

    it('always encodes estop: the reason is sanitized and cut, however it was given', async () => {
      const keyed = new MessageCodec(await createAuthenticator('00112233'));
      const reasons: unknown[] = ['x'.repeat(5000), '\u0001'.repeat(200), 42, {}, 'a\ud800'];
      for (const codec of [new MessageCodec(), keyed]) {
        for (const reason of reasons) {
          const bytes = codec.encode({ cmd: 'estop', seq: 4294967295, sid: 4294967295, reason });
          expect(bytes.length).toBeLessThanOrEqual(MAX_MESSAGE_BYTES);
          const json = new TextDecoder().decode(bytes).replace(/#[0-9a-f]{32}$/, '');
          const sent = JSON.parse(json) as Record<string, unknown>;
          expect(sent['reason']).toBe(sanitizeEstopReason(reason));
          expect(sent).toMatchObject({ cmd: 'estop', seq: 4294967295, sid: 4294967295 });
        }
      }
    });

    it('always encodes stop, dropping anything but the envelope if it would not fit', () => {
      const bytes = new MessageCodec().encode({
        cmd: 'stop',
        seq: 7,
        sid: 9,
        junk: 'y'.repeat(2000),
      });
      expect(JSON.parse(new TextDecoder().decode(bytes))).toEqual({ cmd: 'stop', seq: 7, sid: 9 });
    });
  });
});
