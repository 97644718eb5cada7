import { z } from 'zod';
import type { ColourName } from './palette.js';
import type { Detection } from './project-object.js';
import type { ImageBox } from './seen-object.js';
import { readLabel } from './vlm-labels.js';
import type { VlmKind } from './vlm-labels.js';

/*
 * A vision model's reply read into detections: the JSON taken out of the message (structured
 * output, or a JSON block in text), each entry checked on its own (a malformed one is dropped and
 * counted, the rest kept), boxes turned into pixels and clipped to the image, labels mapped to the
 * palette's colours and the kinds.
 */

/** How a model gives box corners: image pixels, or 0..1000 across the width and height. */
export type VlmBoxUnits = 'pixels' | 'per-mille';

/** A reply that cannot be read at all (no text, a refusal, no JSON, not a list of objects). */
export class VlmReplyError extends Error {
  override readonly name = 'VlmReplyError';
}

const Coordinate = z.number().finite();
const Corners = z.tuple([Coordinate, Coordinate, Coordinate, Coordinate]);

/** One object in a reply: a label, a box `[x0, y0, x1, y1]` (`bbox_2d` as Qwen-VL names it). */
export const VlmObjectSchema = z
  .object({
    label: z.string().trim().min(1),
    box: Corners.optional(),
    bbox_2d: Corners.optional(),
    bbox: Corners.optional(),
    confidence: z.number().finite().min(0).max(100).optional(),
  })
  .refine((o) => (o.box ?? o.bbox_2d ?? o.bbox) !== undefined, {
    message: 'no box [x0, y0, x1, y1]',
  });
export type VlmObject = z.infer<typeof VlmObjectSchema>;

/** The reply as a whole: `{ "objects": [...] }`, or the list alone. */
export const VlmReplySchema = z.union([
  z.object({ objects: z.array(z.unknown()) }),
  z.array(z.unknown()),
]);

/** What became of a reply's entries. */
export interface VlmReplyCounts {
  /** Entries in the reply. */
  received: number;
  /** Kept as detections. */
  kept: number;
  /** Not an object with a label and four finite box coordinates. */
  malformed: number;
  /** Of a colour that is not among the detector's colours (or of none), so not representable. */
  otherColour: number;
  /** Whose box lies wholly outside the image (or has no area). */
  outside: number;
  /** Kept, but with the box cut to the image. */
  clipped: number;
  /** Left out beyond `maxObjects` (the least confident). */
  beyondMax: number;
}

/** The text of a chat completion's `choices[0].message.content` (a string or text parts). */
export function replyText(payload: unknown): string {
  const message = (
    payload as { choices?: { message?: { content?: unknown; refusal?: unknown } }[] } | null
  )?.choices?.[0]?.message;
  const content = message?.content;
  if (typeof content === 'string' && content.trim() !== '') return content;
  if (Array.isArray(content)) {
    const text = content
      .map((part: unknown) => {
        const t = (part as { text?: unknown } | null)?.text;
        return typeof t === 'string' ? t : '';
      })
      .join('');
    if (text.trim() !== '') return text;
  }
  if (typeof message?.refusal === 'string') {
    throw new VlmReplyError(`the model refused: ${message.refusal.slice(0, 200)}`);
  }
  throw new VlmReplyError('the reply has no choices[0].message.content text');
}

/**
 * The JSON value in a model's text: the whole text, else the first fenced block
 * (```` ```json ... ``` ````), else from the first `{` or `[` to the last `}` or `]`.
 */
export function jsonInText(text: string): unknown {
  const attempts = [text.trim()];
  const fenced = /```(?:json)?\s*([\s\S]*?)```/i.exec(text);
  if (fenced?.[1] !== undefined) attempts.push(fenced[1].trim());
  const start = text.search(/[[{]/);
  const end = Math.max(text.lastIndexOf('}'), text.lastIndexOf(']'));
  if (start >= 0 && end > start) attempts.push(text.slice(start, end + 1));
  for (const attempt of attempts) {
    try {
      return JSON.parse(attempt) as unknown;
    } catch {
      // the next way of finding it
    }
  }
  throw new VlmReplyError(`the reply has no JSON in it: ${JSON.stringify(text.slice(0, 120))}`);
}

/** The entries of a reply's text; a VlmReplyError when it is not a list of objects. */
export function replyEntries(text: string): unknown[] {
  const parsed = VlmReplySchema.safeParse(jsonInText(text));
  if (!parsed.success) {
    throw new VlmReplyError('the reply is JSON but not {"objects": [...]} nor a list of objects');
  }
  return Array.isArray(parsed.data) ? parsed.data : parsed.data.objects;
}

/** How a reply's entries are read. */
export interface ReadEntriesOptions {
  width: number;
  height: number;
  units: VlmBoxUnits;
  colours: readonly ColourName[];
  kinds: readonly VlmKind[];
  maxObjects: number;
  /** The detector's name, put on each detection. */
  detector: string;
}

/**
 * A box in the model's units as an inclusive pixel box cut to the image, whether it was cut, or
 * undefined when nothing of it is inside the image. Pixel (i, j) covers [i, i+1) x [j, j+1): a
 * box to x1 = 120 ends in column 119.
 */
export function pixelBox(
  corners: readonly [number, number, number, number],
  width: number,
  height: number,
  units: VlmBoxUnits,
): { box: ImageBox; clipped: boolean } | undefined {
  const sx = units === 'per-mille' ? width / 1000 : 1;
  const sy = units === 'per-mille' ? height / 1000 : 1;
  const [ax, ay, bx, by] = corners;
  const x0 = Math.min(ax, bx) * sx;
  const x1 = Math.max(ax, bx) * sx;
  const y0 = Math.min(ay, by) * sy;
  const y1 = Math.max(ay, by) * sy;
  const cx0 = Math.max(0, x0);
  const cx1 = Math.min(width, x1);
  const cy0 = Math.max(0, y0);
  const cy1 = Math.min(height, y1);
  if (cx1 - cx0 < 1 || cy1 - cy0 < 1) return undefined;
  const box = {
    left: Math.floor(cx0),
    top: Math.floor(cy0),
    right: Math.ceil(cx1) - 1,
    bottom: Math.ceil(cy1) - 1,
  };
  return { box, clipped: cx0 !== x0 || cx1 !== x1 || cy0 !== y0 || cy1 !== y1 };
}

/** A confidence as 0..1: a percentage (above 1) is divided by 100; none given reads as 0.5. */
function unitConfidence(value: number | undefined): number {
  if (value === undefined) return 0.5;
  return Math.round((value > 1 ? value / 100 : value) * 1000) / 1000;
}

/** The detections of a reply's entries, the most confident first, and what became of the rest. */
export function readEntries(
  entries: readonly unknown[],
  options: ReadEntriesOptions,
): { detections: Detection[]; counts: VlmReplyCounts } {
  const counts: VlmReplyCounts = {
    received: entries.length,
    kept: 0,
    malformed: 0,
    otherColour: 0,
    outside: 0,
    clipped: 0,
    beyondMax: 0,
  };
  const detections: Detection[] = [];
  const clipped = new Set<Detection>();
  for (const entry of entries) {
    const parsed = VlmObjectSchema.safeParse(entry);
    if (!parsed.success) {
      counts.malformed += 1;
      continue;
    }
    const object = parsed.data;
    const label = readLabel(object.label, options.colours, options.kinds);
    if (label.colour === undefined) {
      counts.otherColour += 1;
      continue;
    }
    const corners = object.box ?? object.bbox_2d ?? object.bbox;
    if (corners === undefined) {
      counts.malformed += 1;
      continue;
    }
    const placed = pixelBox(corners, options.width, options.height, options.units);
    if (placed === undefined) {
      counts.outside += 1;
      continue;
    }
    const detection: Detection = {
      colour: label.colour,
      kind: label.kind,
      box: placed.box,
      confidence: unitConfidence(object.confidence),
      detector: options.detector,
    };
    if (placed.clipped) clipped.add(detection);
    detections.push(detection);
  }
  detections.sort((a, b) => b.confidence - a.confidence);
  if (detections.length > options.maxObjects) {
    counts.beyondMax = detections.splice(options.maxObjects).length;
  }
  counts.kept = detections.length;
  counts.clipped = detections.filter((d) => clipped.has(d)).length;
  return { detections, counts };
}
