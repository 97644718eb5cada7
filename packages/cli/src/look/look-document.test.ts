import type { FreeSpaceColumn, Percept, SeenObject } from '@hal/perception';
import { V1_CAMERA } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { freeSpaceBins, LookDocumentSchema, lookDocument } from './look-document.js';
import { lookText } from './look-text.js';

const DEG = Math.PI / 180;

function column(
  bearingDeg: number,
  distanceM: number,
  hit: boolean,
  atEdge = false,
): FreeSpaceColumn {
  const to = {
    x: distanceM * Math.cos(bearingDeg * DEG),
    y: distanceM * Math.sin(bearingDeg * DEG),
  };
  return {
    column: 0,
    bearingRad: bearingDeg * DEG,
    distanceM,
    hit,
    atEdge,
    from: { x: 0.2, y: 0 },
    to,
  };
}

const RED_BOX: SeenObject = {
  colour: 'red',
  kind: 'box',
  label: 'red box',
  bearingDeg: 11.98,
  distanceM: 1.0371,
  nearDistanceM: 0.9,
  widthM: 0.3,
  heightM: 0.2,
  confidence: 0.972,
  robot: { x: 1.01, y: 0.215 },
  world: { x: 0.51, y: 0.216 },
  image: { left: 30, top: 0, right: 150, bottom: 60 },
  partial: ['top'],
  detector: 'colour',
};

const PERCEPT: Percept = {
  capturedAt: Date.UTC(2026, 0, 2, 3, 4, 5),
  pose: { x: -0.5, y: 0, yaw: 90 * DEG },
  objects: [RED_BOX],
  freeSpace: [column(12, 2.5, false), column(9, 0.9, true), column(-1, 0.3, true, true)],
  width: 320,
  height: 240,
  floorKnown: true,
  timings: { decodeMs: 1, detectMs: 1, freeSpaceMs: 1, totalMs: 3 },
};

describe('freeSpaceBins', () => {
  it('keeps per 5-degree bin the nearest thing seen, over free floor, left to right', () => {
    const bins = freeSpaceBins([
      column(-3, 2.4, false),
      column(1, 2.5, false),
      column(2, 1.2, true),
      column(2.4, 0.8, true),
      column(-2, 1.5, true),
      column(11, 2.3, false),
    ]);
    expect(bins.map((b) => b.bearingDeg)).toStrictEqual([10, 0, -5]);
    expect(bins[0]).toMatchObject({ fromDeg: 7.5, toDeg: 12.5, freeM: 2.3, blocked: false });
    // the bin from -2.5 to 2.5 degrees: 0.8 m, the nearest of the three things seen in it
    expect(bins[1]).toMatchObject({ freeM: 0.8, blocked: true, atEdge: false });
    expect(bins[2]).toMatchObject({ fromDeg: -7.5, toDeg: -2.5, freeM: 2.4, blocked: false });
  });

  it('never says free beyond the range limit', () => {
    expect(freeSpaceBins([column(0, 3, false)], 5, 2.5)[0]?.freeM).toBe(2.5);
  });
});

describe('lookDocument', () => {
  const doc = lookDocument({
    robot: 'simulator (map empty)',
    deviceId: 'sim-robot-1',
    camera: { ...V1_CAMERA },
    rangeM: 2.5,
    percept: PERCEPT,
    saved: 'look.jpg',
  });

  it('has units in its names, rounded, and passes its own schema', () => {
    expect(LookDocumentSchema.parse(doc)).toStrictEqual(doc);
    expect(doc.capturedAt).toBe('2026-01-02T03:04:05.000Z');
    expect(doc.pose).toStrictEqual({ xM: -0.5, yM: 0, yawDeg: 90 });
    expect(doc.objects[0]).toMatchObject({
      label: 'red box',
      bearingDeg: 11.98,
      distanceM: 1.037,
      world: { xM: 0.51, yM: 0.216 },
      confidence: 0.97,
      cutOff: ['top'],
    });
    expect(doc.freeSpace.map((b) => [b.bearingDeg, b.freeM, b.blocked])).toStrictEqual([
      [10, 0.9, true],
      [0, 0.3, true],
    ]);
  });

  it('is refused by the schema when a field is missing or unknown', () => {
    const { pose: _pose, ...noPose } = doc;
    expect(LookDocumentSchema.safeParse(noPose).success).toBe(false);
    expect(LookDocumentSchema.safeParse({ ...doc, extra: 1 }).success).toBe(false);
    expect(
      LookDocumentSchema.safeParse({ ...doc, objects: [{ ...doc.objects[0], distance: 1 }] })
        .success,
    ).toBe(false);
  });

  it('reads as text: each object with its bearing, distance and place, the free floor per bin', () => {
    const text = lookText(doc);
    expect(text).toContain(
      'simulator (map empty) (sim-robot-1) at x -0.50 m, y 0.00 m, heading 90.0°',
    );
    expect(text).toMatch(
      /red box {2}bearing +\+12\.0° {2}distance 1\.04 m {2}at x 0\.51 m, y 0\.22 m {2}confidence 0\.97 {2}cut off: its top is above the image/,
    );
    expect(text).toMatch(/^ +\+10° {2}free to 0\.90 m, then something$/m);
    expect(text).toMatch(/^ +\+0° {2}blocked at 0\.30 m or nearer \(below the image\)$/m);
    expect(text).toContain('annotated frame saved to look.jpg');
  });

  it('says so when nothing is in view', () => {
    const empty = lookDocument({
      robot: 'r',
      deviceId: 'd',
      camera: { ...V1_CAMERA },
      rangeM: 2.5,
      percept: { ...PERCEPT, objects: [], freeSpace: [column(0, 2.5, false)] },
    });
    expect(lookText(empty)).toContain('no objects in view');
    expect(lookText(empty)).toMatch(/\+0° {2}free to 2\.50 m$/m);
  });
});
