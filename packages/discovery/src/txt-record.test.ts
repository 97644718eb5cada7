import { describe, expect, it } from 'vitest';
import { oversizeTxtEntry, parseAnnouncementTxt } from './txt-record.js';

// What cube-emulator prints in its ready line (the firmware core's announcement).
const EMULATOR_TXT = {
  txtvers: '1',
  device_id: 'cube-emulator',
  proto: '1.1',
  auth: 'none',
  caps: 'locomotion.differential:v1.0,locomotion.stepper:v1.0:steps_per_rev=4096,communication.led:v1.0,safety.estop:v1.0,safety.host_timeout:v1.0',
};

describe('parseAnnouncementTxt', () => {
  it('reads the device id, protocol, auth and capability strings the firmware announces', () => {
    expect(parseAnnouncementTxt(EMULATOR_TXT)).toEqual({
      ok: true,
      announcement: {
        deviceId: 'cube-emulator',
        protocolVersion: '1.1',
        auth: 'none',
        capabilities: [
          'locomotion.differential:v1.0',
          'locomotion.stepper:v1.0:steps_per_rev=4096',
          'communication.led:v1.0',
          'safety.estop:v1.0',
          'safety.host_timeout:v1.0',
        ],
      },
    });
  });

  it('joins a capability list split over caps, caps1 and caps2 in order', () => {
    const parsed = parseAnnouncementTxt({
      ...EMULATOR_TXT,
      caps: 'a.b:v1.0',
      caps1: 'c.d:v1.0,e.f:v2.1',
      caps2: 'g.h:v1.0',
      caps4: 'ignored.gap:v1.0',
    });
    expect(parsed.ok && parsed.announcement.capabilities).toEqual([
      'a.b:v1.0',
      'c.d:v1.0',
      'e.f:v2.1',
      'g.h:v1.0',
    ]);
  });

  it('accepts an empty capability list and ignores unknown entries', () => {
    const parsed = parseAnnouncementTxt({ ...EMULATOR_TXT, caps: '', colour: 'red' });
    expect(parsed.ok && parsed.announcement.capabilities).toEqual([]);
  });

  it.each([
    [{ ...EMULATOR_TXT, device_id: undefined }, 'device_id'],
    [{ ...EMULATOR_TXT, device_id: 'has space' }, 'device ids use letters'],
    [{ ...EMULATOR_TXT, txtvers: '2' }, '"txtvers" must be "1"'],
    [{ ...EMULATOR_TXT, proto: 'one' }, '"proto" must be a version'],
    [{ ...EMULATOR_TXT, auth: 'maybe' }, '"auth" must be one of'],
    [{ ...EMULATOR_TXT, caps: 'locomotion.differential' }, 'has no "v{major}.{minor}" version'],
    [{ ...EMULATOR_TXT, caps1: true }, '"caps1" must be text'],
    [{ ...EMULATOR_TXT, caps: undefined }, 'caps'],
  ])('rejects a malformed record %# and says why', (txt, why) => {
    const parsed = parseAnnouncementTxt(txt);
    expect(parsed.ok).toBe(false);
    expect(!parsed.ok && parsed.reason).toContain(why);
  });

  it.each([null, 'text', 42, []])('rejects a record that is not an object (%j)', (txt) => {
    expect(parseAnnouncementTxt(txt).ok).toBe(false);
  });
});

describe('oversizeTxtEntry', () => {
  it('names the first entry whose key=value passes 255 bytes, counting UTF-8 bytes', () => {
    expect(oversizeTxtEntry(EMULATOR_TXT)).toBeUndefined();
    expect(oversizeTxtEntry({ caps: 'x'.repeat(250) })).toBeUndefined(); // 255 bytes
    expect(oversizeTxtEntry({ ok: 'y', caps: 'x'.repeat(251) })).toBe('caps');
    expect(oversizeTxtEntry({ name: 'é'.repeat(126) })).toBe('name'); // 5 + 252 bytes
  });
});
