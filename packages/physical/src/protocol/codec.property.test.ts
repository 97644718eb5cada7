import { fc, it } from '@fast-check/vitest';
import { HalError } from '@hal/types';
import { describe, expect } from 'vitest';
import { createAuthenticator } from './auth.js';
import { MAX_MESSAGE_BYTES, MessageCodec } from './codec.js';

// Property tests of the message codec: decoding never throws and only accepts what a device with
// the same key could have sent; encoding always yields a message within the protocol's limit or a
// typed error.

const key = await createAuthenticator('00112233445566778899aabbccddeeff');
const otherKey = await createAuthenticator('00112233445566778899aabbccddeefe');
const keyless = new MessageCodec();
const keyed = new MessageCodec(key);

const encoder = new TextEncoder();
const decoder = new TextDecoder();

/** A reply as a device writes it: the envelope plus any other JSON fields. */
const replyArb = fc
  .record(
    {
      ok: fc.boolean(),
      seq: fc.integer({ min: 0, max: 4_294_967_295 }),
      sid: fc.integer({ min: 0, max: 4_294_967_295 }),
      cmd: fc.string({ maxLength: 16 }),
      extra: fc.dictionary(
        fc
          .string({ maxLength: 8 })
          .filter((k) => !['ok', 'seq', 'sid', 'cmd', 'error', '__proto__'].includes(k)),
        fc.jsonValue({ maxDepth: 2 }),
        { maxKeys: 4 },
      ),
    },
    { requiredKeys: ['ok', 'extra'] },
  )
  .map(({ extra, ...envelope }) => ({ ...extra, ...envelope }))
  // a reply fits in one message, MAC included
  .filter((reply) => encoder.encode(JSON.stringify(reply)).length <= MAX_MESSAGE_BYTES - 33);

/** Any bytes, or text that looks like a reply, or a reply with a MAC-like suffix. */
const inboundArb = fc.oneof(
  fc.uint8Array({ maxLength: 200 }),
  fc.jsonValue().map((v) => encoder.encode(JSON.stringify(v))),
  fc
    .tuple(fc.jsonValue(), fc.stringMatching(/^[0-9a-f]{32}$/))
    .map(([v, mac]) => encoder.encode(`${JSON.stringify(v)}#${mac}`)),
);

describe('MessageCodec.decode', () => {
  it.prop([inboundArb], { numRuns: 300 })(
    'never throws: any input is a reply or a MALFORMED / AUTH_FAILED error',
    (bytes) => {
      for (const codec of [keyless, keyed]) {
        const result = codec.decode(bytes);
        if (result.ok) {
          expect(typeof result.reply.ok).toBe('boolean');
        } else {
          expect(result.error).toBeInstanceOf(HalError);
          expect(['MALFORMED', 'AUTH_FAILED']).toContain(result.error.code);
        }
      }
    },
  );

  it.prop([fc.string({ maxLength: 40 }), fc.integer({ min: 309, max: 5000 })], { numRuns: 100 })(
    'refuses a number too large for a double instead of reading it as Infinity',
    (cmd, exponent) => {
      const text = `{"ok":true,"cmd":${JSON.stringify(cmd)},"seq":1e${exponent}}`;
      const result = keyless.decode(encoder.encode(text));
      expect(result.ok).toBe(false);
    },
  );

  it.prop([replyArb], { numRuns: 200 })(
    'reads back what a device with the same key signed, field for field',
    (reply) => {
      const bytes = keyed.encode(reply);
      const result = keyed.decode(bytes);
      expect(result.ok).toBe(true);
      if (result.ok) expect(result.reply).toEqual(JSON.parse(JSON.stringify(reply)));
      // A host without a key still reads a signed reply (to say why it was refused).
      expect(keyless.decode(bytes).ok).toBe(true);
    },
  );

  it.prop([replyArb, fc.nat(), fc.integer({ min: 1, max: 255 })], { numRuns: 300 })(
    'refuses a signed reply with any byte changed, or signed with another key',
    (reply, where, delta) => {
      const bytes = keyed.encode(reply).slice();
      const at = where % bytes.length;
      bytes[at] = ((bytes[at] ?? 0) + delta) & 0xff;
      expect(keyed.decode(bytes).ok).toBe(false);
      expect(keyed.decode(new MessageCodec(otherKey).encode(reply)).ok).toBe(false);
    },
  );

  it.prop([replyArb], { numRuns: 100 })('refuses an unsigned reply when a key is set', (reply) => {
    const result = keyed.decode(keyless.encode(reply));
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.error.code).toBe('AUTH_FAILED');
  });
});

describe('MessageCodec.encode', () => {
  const commands = ['hello', 'move_steps', 'move_cm', 'drive', 'get_status', 'set_led'];
  const requestArb = fc
    .record({
      cmd: fc.constantFrom(...commands),
      seq: fc.integer({ min: 0, max: 4_294_967_295 }),
      params: fc.dictionary(
        fc.string({ maxLength: 12 }).filter((k) => k !== '__proto__'),
        fc.jsonValue({ maxDepth: 2 }),
        { maxKeys: 6 },
      ),
    })
    .map(({ cmd, seq, params }) => ({ ...params, cmd, seq }));

  it.prop([requestArb, fc.boolean()], { numRuns: 200 })(
    'yields at most 1024 bytes that read back as the request, or a RANGE_EXCEEDED error',
    (request, signed) => {
      const codec = signed ? keyed : keyless;
      let bytes: Uint8Array;
      try {
        bytes = codec.encode(request);
      } catch (error) {
        expect(error).toBeInstanceOf(HalError);
        expect((error as HalError).code).toBe('RANGE_EXCEEDED');
        expect(encoder.encode(JSON.stringify(request)).length).toBeGreaterThan(
          MAX_MESSAGE_BYTES - (signed ? 33 : 0),
        );
        return;
      }
      expect(bytes.length).toBeLessThanOrEqual(MAX_MESSAGE_BYTES);
      const json = signed ? bytes.subarray(0, bytes.length - 33) : bytes;
      expect(JSON.parse(decoder.decode(json))).toEqual(JSON.parse(JSON.stringify(request)));
    },
  );
});
