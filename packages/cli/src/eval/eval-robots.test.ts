import { describe, expect, it } from 'vitest';
import { emulatorHostTimeoutMs, parsePlaces } from './eval-robots.js';

describe('the emulator hal eval starts', () => {
  it("keeps the host timeout's 2 s of real time at any clock speed, within the firmware's 10 s", () => {
    expect(emulatorHostTimeoutMs(1)).toBe(2000);
    expect(emulatorHostTimeoutMs(0.5)).toBe(2000);
    expect(emulatorHostTimeoutMs(4)).toBe(8000);
    expect(emulatorHostTimeoutMs(10)).toBe(10_000);
  });
});

describe('parsePlaces', () => {
  it('reads sim, emulator and udp:// places, and refuses one named twice', () => {
    expect(parsePlaces('sim,emulator,udp://127.0.0.1:4210')).toEqual([
      { kind: 'sim' },
      { kind: 'emulator' },
      { kind: 'udp', host: '127.0.0.1', port: 4210 },
    ]);
    expect(() => parsePlaces('sim,sim')).toThrow(/names a place twice/);
  });
});
