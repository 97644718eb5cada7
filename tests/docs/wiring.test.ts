// The hardware guide's wiring (docs/hardware.md's table and docs/images/wiring.svg) names the
// pins the firmware drives (firmware/esp32-s3-stepper/src/platform/esp32/board.h), so the drawing
// cannot drift from the code.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

const read = (path: string): string =>
  readFileSync(new URL(`../../${path}`, import.meta.url), 'utf8');
const board = read('firmware/esp32-s3-stepper/src/platform/esp32/board.h');
const guide = read('docs/hardware.md');
const drawing = read('docs/images/wiring.svg');

function pins(name: string): number[] {
  const list = new RegExp(String.raw`${name}\[4\]\s*=\s*\{([^}]*)\}`).exec(board)?.[1];
  if (list === undefined) throw new Error(`board.h has no ${name}[4]`);
  return list.split(',').map((p) => Number(p.trim()));
}

describe('the wiring in docs/hardware.md and docs/images/wiring.svg', () => {
  const left = pins('kLeftPins');
  const right = pins('kRightPins');

  it("lists the firmware's motor pins, IN1 to IN4, in the guide's table", () => {
    const [l1, ...lRest] = left;
    const [r1, ...rRest] = right;
    expect(guide).toContain(`| GPIO${l1}, ${lRest.join(', ')} | left ULN2003 IN1, IN2, IN3, IN4 |`);
    expect(guide).toContain(
      `| GPIO${r1}, ${rRest.join(', ')} | right ULN2003 IN1, IN2, IN3, IN4 |`,
    );
  });

  it('draws every one of them, in order, and the guide shows the drawing', () => {
    const labels = [...drawing.matchAll(/>GPIO(\d+)</g)].map((m) => Number(m[1]));
    expect(labels).toEqual([...left, ...right]);
    expect(drawing).toMatch(/^<svg [^>]*xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
    expect(guide).toContain('](images/wiring.svg)');
  });

  it("names the LED's default pin and the option for v1.1 boards as the firmware has them", () => {
    const fallback = /constexpr uint8_t kRgbLedPin = (\d+);/.exec(board)?.[1];
    expect(fallback).toBe('48');
    expect(drawing).toContain(`GPIO${fallback} on v1.0`);
    expect(guide).toContain('#define CUBE_RGB_LED_PIN 38');
    expect(read('firmware/esp32-s3-stepper/src/board_options.example.h')).toContain(
      '// #define CUBE_RGB_LED_PIN 38',
    );
  });
});
