import { ROBOT_SETTINGS } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { DeviceConfigSchema } from './schemas.js';

describe('DeviceConfigSchema', () => {
  it('reads each config field as the settings table says the firmware writes it', () => {
    const valid = Object.fromEntries(
      ROBOT_SETTINGS.filter((s) => s.wire !== null && s.wireType !== null).map((s) => [
        s.wire,
        s.default,
      ]),
    );
    expect(DeviceConfigSchema.safeParse(valid).success).toBe(true);
    for (const setting of ROBOT_SETTINGS) {
      if (setting.wire === null || setting.wireType === null) continue;
      const fractional = { ...valid, [setting.wire]: setting.default + 0.5 };
      expect(DeviceConfigSchema.safeParse(fractional).success, setting.wire).toBe(
        setting.wireType === 'double',
      );
    }
  });

  it('names every field of the table that the firmware writes, and no other', () => {
    const wire = ROBOT_SETTINGS.filter((s) => s.wireType !== null).map((s) => s.wire);
    expect(Object.keys(DeviceConfigSchema.shape).sort()).toEqual(wire.sort());
  });
});
