// What `hal look --json` prints: one JSON document of what the robot sees now, checked by a zod
// schema (units in the names: metres `M`, degrees `Deg`; REP-103, bearings left positive), made
// from one perception look.
import type { FreeSpaceColumn, Percept } from '@hal/perception';
import { CameraModelSchema } from '@hal/types';
import type { CameraModel } from '@hal/types';
import { z } from 'zod';

const RAD_TO_DEG = 180 / Math.PI;

const PointSchema = z.object({ xM: z.number(), yM: z.number() }).strict();

/** One object the camera sees. */
export const LookObjectSchema = z
  .object({
    label: z.string().describe('Words for it, e.g. "red box"'),
    colour: z.string(),
    kind: z.enum(['box', 'pillar', 'unknown']),
    bearingDeg: z.number().describe("Bearing of its centre from the robot's heading, left +"),
    distanceM: z.number().describe("Ground distance from the robot's centre to its centre"),
    nearDistanceM: z.number().describe('Ground distance to the nearest point of its base'),
    widthM: z.number(),
    heightM: z.number().describe('A lower bound when its top is cut off'),
    confidence: z.number().min(0).max(1),
    world: PointSchema.describe('Its centre in the odometry frame, from the pose at capture'),
    robot: PointSchema.describe("Its centre in the robot's frame at capture"),
    image: z
      .object({ left: z.number(), top: z.number(), right: z.number(), bottom: z.number() })
      .strict()
      .describe('Its pixel box, inclusive'),
    cutOff: z
      .array(z.enum(['base', 'side', 'top']))
      .describe(
        'What of it is out of view: base (nearer than the nearest visible floor), side, top',
      ),
  })
  .strict();

/** How far the floor is free in one bin of bearings. */
export const LookFreeSpaceSchema = z
  .object({
    bearingDeg: z.number().describe("The bin's centre, left +"),
    fromDeg: z.number(),
    toDeg: z.number(),
    freeM: z
      .number()
      .describe(
        "Distance from the robot's centre to the nearest thing seen in the bin, or the range limit",
      ),
    blocked: z.boolean().describe('Something that is not floor was seen (false: free to freeM)'),
    atEdge: z
      .boolean()
      .describe("The thing reaches below the image's bottom: it is at freeM or nearer"),
  })
  .strict();

/** The whole document. */
export const LookDocumentSchema = z
  .object({
    robot: z.string().describe('Which robot looked'),
    deviceId: z.string(),
    capturedAt: z.iso.datetime().describe('When the frame was taken (ISO 8601, UTC)'),
    pose: z
      .object({ xM: z.number(), yM: z.number(), yawDeg: z.number() })
      .strict()
      .describe("The robot's believed (odometry) pose at capture"),
    camera: CameraModelSchema.describe('The camera model perception projected with'),
    floorKnown: z.boolean().describe("Whether the floor's look was learnt"),
    rangeM: z.number().describe('How far the floor is judged'),
    objects: z.array(LookObjectSchema).describe('Nearest first'),
    freeSpace: z.array(LookFreeSpaceSchema).describe('Left to right'),
    saved: z.string().optional().describe('The annotated frame written with --save'),
  })
  .strict();

export type LookObject = z.infer<typeof LookObjectSchema>;
export type LookFreeSpace = z.infer<typeof LookFreeSpaceSchema>;
export type LookDocument = z.infer<typeof LookDocumentSchema>;

const round = (value: number, digits = 3): number => {
  const scale = 10 ** digits;
  return Math.round(value * scale) / scale;
};

/**
 * The free space in bins of `binDeg` degrees of bearing, centred on multiples of it, left to
 * right: per bin the nearest boundary of its columns (free to the range limit when none).
 */
export function freeSpaceBins(
  columns: readonly FreeSpaceColumn[],
  binDeg = 5,
  rangeM = 2.5,
): LookFreeSpace[] {
  const bins = new Map<number, LookFreeSpace>();
  for (const column of columns) {
    // (+ 0: a bearing just right of straight ahead is bin 0, not -0)
    const bin = Math.round((column.bearingRad * RAD_TO_DEG) / binDeg) + 0;
    const seen = bins.get(bin);
    const freeM = column.hit ? column.distanceM : Math.min(rangeM, column.distanceM);
    if (seen === undefined) {
      bins.set(bin, {
        bearingDeg: bin * binDeg,
        fromDeg: (bin - 0.5) * binDeg,
        toDeg: (bin + 0.5) * binDeg,
        freeM,
        blocked: column.hit,
        atEdge: column.atEdge,
      });
      continue;
    }
    // a boundary seen beats free floor; the nearer of two of the same kind
    if ((column.hit && !seen.blocked) || (column.hit === seen.blocked && freeM < seen.freeM)) {
      seen.freeM = freeM;
      seen.blocked = column.hit;
      seen.atEdge = column.atEdge;
    }
  }
  return [...bins.values()]
    .sort((a, b) => b.bearingDeg - a.bearingDeg)
    .map((b) => ({ ...b, freeM: round(b.freeM) }));
}

/** What `hal look` says about one look. */
export interface LookSource {
  robot: string;
  deviceId: string;
  camera: CameraModel;
  rangeM: number;
  percept: Percept;
  saved?: string;
}

/** The document of one look (checked against {@link LookDocumentSchema}). */
export function lookDocument(source: LookSource): LookDocument {
  const { percept } = source;
  const doc: LookDocument = {
    robot: source.robot,
    deviceId: source.deviceId,
    capturedAt: new Date(percept.capturedAt).toISOString(),
    pose: {
      xM: round(percept.pose.x),
      yM: round(percept.pose.y),
      yawDeg: round(percept.pose.yaw * RAD_TO_DEG, 2),
    },
    camera: { ...source.camera },
    floorKnown: percept.floorKnown,
    rangeM: source.rangeM,
    objects: percept.objects.map((o) => ({
      label: o.label,
      colour: o.colour,
      kind: o.kind,
      bearingDeg: round(o.bearingDeg, 2),
      distanceM: round(o.distanceM),
      nearDistanceM: round(o.nearDistanceM),
      widthM: round(o.widthM),
      heightM: round(o.heightM),
      confidence: round(o.confidence, 2),
      world: { xM: round(o.world.x), yM: round(o.world.y) },
      robot: { xM: round(o.robot.x), yM: round(o.robot.y) },
      image: { ...o.image },
      cutOff: [...o.partial],
    })),
    freeSpace: freeSpaceBins(percept.freeSpace, 5, source.rangeM),
    ...(source.saved === undefined ? {} : { saved: source.saved }),
  };
  return LookDocumentSchema.parse(doc);
}
