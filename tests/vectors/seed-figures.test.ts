import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

// The robot specification's figures live in the project's shared folder, beside the repository
// where the project is developed and tested (CI lays it there); a clone of the repository alone
// has only this copy, which the kinematics tests read. This keeps the copy from drifting.
const shared = new URL('../../../shared/vectors/seed-figures.json', import.meta.url);
const copy = new URL('./seed-figures.json', import.meta.url);

describe.runIf(existsSync(shared))('tests/vectors/seed-figures.json', () => {
  it('is byte for byte the specification figures in ../shared/vectors', () => {
    expect(readFileSync(copy, 'utf8')).toBe(readFileSync(shared, 'utf8'));
  });
});
