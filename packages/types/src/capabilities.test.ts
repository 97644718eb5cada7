import { describe, expect, it } from 'vitest';
import {
  CAPABILITIES,
  findCapability,
  formatCapability,
  hasCapability,
  isCapabilityCompatible,
  parseCapability,
} from './capabilities.js';
import { HalError } from './errors.js';

describe('parseCapability', () => {
  it('parses domain, type, version and metadata', () => {
    expect(parseCapability('locomotion.stepper:v1.2:steps_per_rev=4096:wheel=6cm')).toEqual({
      domain: 'locomotion',
      type: 'stepper',
      major: 1,
      minor: 2,
      metadata: { steps_per_rev: '4096', wheel: '6cm' },
    });
  });

  it.each([
    ['locomotion:v1.0', /"{domain}.{type}"/],
    ['Locomotion.drive:v1.0', /invalid domain/],
    ['locomotion.drive', /version/],
    ['locomotion.drive:1.0', /version/],
    ['locomotion.drive:v1', /version/],
    ['locomotion.drive:v01.0', /version/],
    ['locomotion.drive:v1.0:novalue', /key=value/],
    ['locomotion.drive:v1.0:a=1:a=2', /repeats/],
  ])('refuses "%s" with INVALID_PARAMETER', (text, why) => {
    expect(() => parseCapability(text)).toThrow(HalError);
    expect(() => parseCapability(text)).toThrow(why);
  });

  it('round-trips through formatCapability with sorted metadata', () => {
    const text = 'vision.camera:v1.0:fps=10:res=320x240';
    expect(formatCapability(parseCapability(text))).toBe(text);
    expect(
      formatCapability({
        domain: 'vision',
        type: 'camera',
        major: 1,
        minor: 0,
        metadata: { res: '320x240', fps: '10' },
      }),
    ).toBe(text);
  });

  it('refuses to format an invalid capability', () => {
    expect(() =>
      formatCapability({ domain: 'x', type: 'y', major: -1, minor: 0, metadata: {} }),
    ).toThrow(HalError);
    expect(() =>
      formatCapability({ domain: 'x', type: 'y', major: 1, minor: 0, metadata: { k: 'a:b' } }),
    ).toThrow(HalError);
  });
});

describe('isCapabilityCompatible', () => {
  it('accepts the same major with an equal or newer minor', () => {
    expect(isCapabilityCompatible('safety.estop:v1.3', 'safety.estop:v1.2')).toBe(true);
    expect(isCapabilityCompatible('safety.estop:v1.2', 'safety.estop:v1.2')).toBe(true);
  });

  it('refuses an older minor, another major, or another name', () => {
    expect(isCapabilityCompatible('safety.estop:v1.1', 'safety.estop:v1.2')).toBe(false);
    expect(isCapabilityCompatible('safety.estop:v2.5', 'safety.estop:v1.0')).toBe(false);
    expect(isCapabilityCompatible('safety.watchdog:v1.0', 'safety.estop:v1.0')).toBe(false);
  });

  it('finds a matching capability in a device list', () => {
    const offered = [CAPABILITIES.differentialDrive, 'locomotion.stepper:v1.0:steps_per_rev=4096'];
    expect(findCapability(offered, 'locomotion.stepper:v1.0')?.metadata).toEqual({
      steps_per_rev: '4096',
    });
    expect(hasCapability(offered, CAPABILITIES.speaker)).toBe(false);
  });
});
