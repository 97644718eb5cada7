import { describe, expect, it } from 'vitest';
import { decideFollowerAction, formationOffsets, slotPosition } from './formation.js';

describe('formation geometry', () => {
  it("turns an offset into the world by the leader's heading (REP-103, yaw counter-clockwise)", () => {
    const slot = slotPosition({ x: 1, y: 2, yaw: Math.PI / 2 }, { x: -0.5, y: 0 });
    // the leader faces +y, so "behind" is -y
    expect(slot.x).toBeCloseTo(1, 9);
    expect(slot.y).toBeCloseTo(1.5, 9);
    const left = slotPosition({ x: 0, y: 0, yaw: 0 }, { x: 0, y: 0.3 });
    expect(left).toEqual({ x: 0, y: 0.3 });
  });

  it('lays out column, line and wedge formations', () => {
    expect(formationOffsets('column', ['a', 'b'], 0.2)).toEqual({
      a: { x: -0.2, y: 0 },
      b: { x: -0.4, y: 0 },
    });
    expect(formationOffsets('line', ['a', 'b', 'c'], 0.2)).toEqual({
      a: { x: 0, y: 0.2 },
      b: { x: 0, y: -0.2 },
      c: { x: 0, y: 0.4 },
    });
    expect(formationOffsets('wedge', ['a', 'b', 'c'], 0.2)).toEqual({
      a: { x: -0.2, y: 0.2 },
      b: { x: -0.2, y: -0.2 },
      c: { x: -0.4, y: 0.4 },
    });
  });

  it('refuses an unknown shape or a spacing that is not a positive number', () => {
    expect(() => formationOffsets('circle' as never, ['a'], 0.2)).toThrow(/column, line, wedge/);
    expect(() => formationOffsets('line', ['a'], Number.NaN)).toThrow(/spacing/);
    expect(() => formationOffsets('line', ['a'], 0)).toThrow(/spacing/);
  });

  it('drives to the slot when out of tolerance, then turns to the leader heading, then holds', () => {
    const base = { toleranceM: 0.03, headingToleranceRad: 0.1, alignHeading: true, leaderYaw: 0 };
    expect(
      decideFollowerAction({ ...base, pose: { x: 0, y: 0, yaw: 0 }, slot: { x: 0.1, y: 0 } }),
    ).toEqual({ kind: 'moveTo', x: 0.1, y: 0 });
    const turn = decideFollowerAction({
      ...base,
      pose: { x: 0.1, y: 0, yaw: -Math.PI / 2 },
      slot: { x: 0.1, y: 0 },
    });
    expect(turn).toMatchObject({ kind: 'rotate', direction: 'left' });
    expect(turn.kind === 'rotate' && turn.degrees).toBeCloseTo(90, 6);
    expect(
      decideFollowerAction({
        ...base,
        pose: { x: 0.1, y: 0.01, yaw: 0.05 },
        slot: { x: 0.1, y: 0 },
      }),
    ).toEqual({ kind: 'hold' });
    expect(
      decideFollowerAction({
        ...base,
        alignHeading: false,
        pose: { x: 0.1, y: 0, yaw: 3 },
        slot: { x: 0.1, y: 0 },
      }),
    ).toEqual({ kind: 'hold' });
  });
});
