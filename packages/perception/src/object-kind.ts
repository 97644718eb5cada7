import type { ObjectKind } from './seen-object.js';

/**
 * Box or pillar, from how brightness runs across the object's columns: a box shows one or two
 * flat faces (constant across one face, a single step between two), a pillar shades from a
 * bright middle down to both of its sides. Too narrow, or neither clearly, is unknown.
 */
export function kindFromShading(
  columnBrightness: Float32Array,
  columnCount: Uint16Array,
  minColumns = 8,
): ObjectKind {
  const means: number[] = [];
  for (let c = 0; c < columnBrightness.length; c += 1) {
    const n = columnCount[c] ?? 0;
    if (n >= 3) means.push((columnBrightness[c] ?? 0) / n);
  }
  // The outermost columns mix with the background: leave them out.
  const trimmed = means.slice(2, -2);
  // A 3-column moving average takes the JPEG's blocky noise out of the profile.
  const inner = trimmed.map((m, i) => ((trimmed[i - 1] ?? m) + m + (trimmed[i + 1] ?? m)) / 3);
  if (inner.length < minColumns) return 'unknown';
  const peak = Math.max(...inner);
  const least = Math.min(...inner);
  if (!(peak > 0)) return 'unknown';
  const range = (peak - least) / peak;
  if (range < 0.08) return 'box';
  let largestStep = 0;
  let travel = 0;
  for (let i = 1; i < inner.length; i += 1) {
    const step = Math.abs((inner[i] ?? 0) - (inner[i - 1] ?? 0)) / peak;
    largestStep = Math.max(largestStep, step);
    travel += step;
  }
  // A round body: brightest in its middle, darker towards both sides.
  const top = inner.indexOf(peak);
  const leftDrop = (peak - Math.min(...inner.slice(0, top + 1))) / peak;
  const rightDrop = (peak - Math.min(...inner.slice(top))) / peak;
  const middle = top >= 0.2 * (inner.length - 1) && top <= 0.8 * (inner.length - 1);
  if (range >= 0.12 && middle && leftDrop >= 0.4 * range && rightDrop >= 0.4 * range) {
    return 'pillar';
  }
  // Two flat faces: brightness changes once, from one face's to the other's.
  if (travel <= 1.8 * range && largestStep >= 0.1 * range) return 'box';
  return 'unknown';
}
