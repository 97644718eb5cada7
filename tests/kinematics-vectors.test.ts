import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { buildKinematicsVectors, KINEMATICS_VECTORS_PATH } from './vectors/kinematics-vectors.js';

describe('tests/vectors/kinematics.json', () => {
  it('equals what @hal/kinematics computes (run `pnpm vectors:write` after a deliberate change)', () => {
    const committed: unknown = JSON.parse(readFileSync(KINEMATICS_VECTORS_PATH, 'utf8'));
    expect(committed).toEqual(JSON.parse(JSON.stringify(buildKinematicsVectors())));
  });

  it('holds the specification figures: 1706 steps per wheel for 90 degrees, 10 cm = 2172 steps', () => {
    const vectors = buildKinematicsVectors();
    expect(vectors.rotation_to_steps.find((r) => r.degrees === 90)).toEqual({
      degrees: 90,
      left_steps: -1706,
      right_steps: 1706,
    });
    expect(vectors.distance_to_steps.find((r) => r.distance_cm === 10)?.steps).toBe(2172);
  });
});
