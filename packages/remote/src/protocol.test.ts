import { describe, expect, it } from 'vitest';
import { decodeArgs, decodeMessage, encodeArgs, encodeMessage } from './protocol.js';

describe('protocol', () => {
  it('carries NaN, Infinity and undefined arguments across JSON unchanged', () => {
    const args = [
      Number.NaN,
      Number.POSITIVE_INFINITY,
      undefined,
      Number.NEGATIVE_INFINITY,
      1,
      undefined,
    ];
    const wire = JSON.parse(JSON.stringify(encodeArgs(args))) as unknown[];
    expect(wire).toHaveLength(5);
    expect(decodeArgs(wire)).toEqual([
      Number.NaN,
      Number.POSITIVE_INFINITY,
      undefined,
      Number.NEGATIVE_INFINITY,
      1,
    ]);
  });

  it('leaves ordinary objects that merely look tagged alone', () => {
    expect(decodeArgs([{ $number: 'NaN', extra: 1 }, 'NaN'])).toEqual([
      { $number: 'NaN', extra: 1 },
      'NaN',
    ]);
  });

  it('round-trips a call in a Tafy envelope naming the sender', () => {
    const text = encodeMessage(
      'hal.remote.call',
      { deviceId: 'ui-1' },
      { id: '7', call: 'stop', args: [] },
    );
    const message = decodeMessage(text);
    expect(message.schema).toBe('hal.remote.call');
    expect(message.envelope).toMatchObject({
      hal_major: 1,
      device_id: 'ui-1',
      payload: { id: '7', call: 'stop' },
    });
  });

  it.each([
    ['not JSON', '{', /not JSON/],
    ['not an envelope', '{"a":1}', /not a HAL envelope/],
    [
      'an unknown schema',
      JSON.stringify({
        hal_major: 1,
        hal_minor: 0,
        schema: 'x.y',
        device_id: 'a',
        caps: [],
        ts: 0,
        payload: {},
      }),
      /unknown message schema "x.y"/,
    ],
    [
      'a newer major version',
      JSON.stringify({
        hal_major: 2,
        hal_minor: 0,
        schema: 'hal.remote.heartbeat',
        device_id: 'a',
        caps: [],
        ts: 0,
        payload: {},
      }),
      /hal_major 2/,
    ],
    [
      'a call without args',
      JSON.stringify({
        hal_major: 1,
        hal_minor: 0,
        schema: 'hal.remote.call',
        device_id: 'a',
        caps: [],
        ts: 0,
        payload: { id: '1', call: 'stop' },
      }),
      /payload does not match/,
    ],
  ])('refuses %s with MALFORMED', (_what, text, message) => {
    expect(() => decodeMessage(text)).toThrow(message);
    try {
      decodeMessage(text);
    } catch (e) {
      expect((e as { code: string }).code).toBe('MALFORMED');
    }
  });
});
