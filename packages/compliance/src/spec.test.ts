import { CAPABILITIES } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { LATENCY_CLASSES, announces, specCapability } from './spec.js';

describe('announces', () => {
  it("recognises the spec's capability names and the ones this library's HALs announce", () => {
    expect(announces(['motor.differential:v1.0:priority=high'], 'motor.differential')).toBe(true);
    expect(announces([CAPABILITIES.differentialDrive], 'motor.differential')).toBe(true);
    expect(announces([CAPABILITIES.camera], 'camera')).toBe(true);
    expect(announces([CAPABILITIES.imu], 'sensor.imu')).toBe(true);
    expect(announces(['sensor.range.tof:v1.0:count=3'], 'sensor.range')).toBe(true);
    expect(announces([CAPABILITIES.emergencyStop], 'safety')).toBe(true);
  });

  it('does not confuse one capability for another, and counts system as always served', () => {
    const caps = [CAPABILITIES.differentialDrive, CAPABILITIES.led, 'safety.host_timeout:v1.0'];
    expect(announces(caps, 'camera')).toBe(false);
    expect(announces(caps, 'safety')).toBe(false);
    expect(announces(['sensor.rangefinder:v1.0'], 'sensor.range')).toBe(false);
    expect(announces([], 'system')).toBe(true);
  });
});

describe('specCapability', () => {
  it('takes the names the runner knows and nothing else', () => {
    expect(specCapability('motor.differential')).toBe('motor.differential');
    expect(specCapability('motor')).toBeUndefined();
    expect(specCapability('')).toBeUndefined();
  });
});

describe('LATENCY_CLASSES', () => {
  it("holds the spec's figures: real-time 1 ms, low-latency 10 ms, interactive 100 ms", () => {
    expect(Object.values(LATENCY_CLASSES).map((c) => [c.name, c.limitMs])).toEqual([
      ['real-time', 1],
      ['low-latency', 10],
      ['interactive', 100],
    ]);
  });
});
