import { describe, expect, it } from 'vitest';
import { parseCommandSpec } from './command-spec.js';

describe('hal fleet run --command', () => {
  it('reads the short forms and JSON as fleet commands', () => {
    // a bare distance is metres, as in hal drive and hal record; a unit may be given
    expect(parseCommandSpec('forward:0.05')).toEqual({ kind: 'moveForward', distanceCm: 5 });
    expect(parseCommandSpec('forward:5')).toEqual({ kind: 'moveForward', distanceCm: 500 });
    expect(parseCommandSpec('forward:5cm')).toEqual({ kind: 'moveForward', distanceCm: 5 });
    expect(parseCommandSpec('forward:0.07m')).toEqual({ kind: 'moveForward', distanceCm: 7 });
    expect(parseCommandSpec('backward:25mm')).toEqual({ kind: 'moveBackward', distanceCm: 2.5 });
    expect(parseCommandSpec('rotate:right:1.5rad')).toMatchObject({ degrees: 85.9436692696 });
    expect(parseCommandSpec('moveTo:50cm,-0.2m')).toEqual({ kind: 'moveTo', x: 0.5, y: -0.2 });
    expect(parseCommandSpec('rotate:left:90')).toEqual({
      kind: 'rotate',
      direction: 'left',
      degrees: 90,
    });
    expect(parseCommandSpec('moveTo:0.5,-0.2')).toEqual({ kind: 'moveTo', x: 0.5, y: -0.2 });
    expect(parseCommandSpec('moveTo:0.5,0.2,0.03')).toMatchObject({ speed: 0.03 });
    expect(parseCommandSpec('drive:100,-100,500')).toEqual({
      kind: 'drive',
      left: 100,
      right: -100,
      durationMs: 500,
    });
    expect(parseCommandSpec('led:0,255,0')).toEqual({ kind: 'setLED', r: 0, g: 255, b: 0 });
    expect(parseCommandSpec('stop')).toEqual({ kind: 'stop' });
    expect(parseCommandSpec('{"kind":"moveForward","distanceCm":3}')).toEqual({
      kind: 'moveForward',
      distanceCm: 3,
    });
  });

  it('refuses anything else with a USAGE error naming the accepted forms', () => {
    for (const bad of [
      'fly:3',
      'forward',
      'forward:',
      'forward:abc',
      'forward:NaN',
      'moveTo:1',
      'moveTo:1,2,3,4',
      'rotate:up:90',
      'drive:1,,2',
      '{"kind":"moveForward"',
      '{"kind":"teleport"}',
    ]) {
      expect(() => parseCommandSpec(bad), bad).toThrow(
        expect.objectContaining({ name: 'CliError', code: 'USAGE' }),
      );
    }
    expect(() => parseCommandSpec('fly:3')).toThrow(/forward:<distance>/);
    expect(() => parseCommandSpec('forward:5deg')).toThrow(/expected forward:<distance>/);
    expect(() => parseCommandSpec('rotate:up:90')).toThrow(/direction/);
  });
});
