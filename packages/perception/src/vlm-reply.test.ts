import { describe, expect, it } from 'vitest';
import { COLOUR_NAMES } from './palette.js';
import { readLabel, VLM_KINDS } from './vlm-labels.js';
import { jsonInText, pixelBox, readEntries, replyEntries, replyText } from './vlm-reply.js';
import type { ReadEntriesOptions } from './vlm-reply.js';

const options: ReadEntriesOptions = {
  width: 320,
  height: 240,
  units: 'pixels',
  colours: COLOUR_NAMES,
  kinds: VLM_KINDS,
  maxObjects: 10,
  detector: 'vlm:test',
};

describe('readLabel', () => {
  it('reads the colour and the kind, with the words models use for them', () => {
    expect(readLabel('red box')).toEqual({ colour: 'red', kind: 'box' });
    expect(readLabel('Blue Cylinder')).toEqual({ colour: 'blue', kind: 'pillar' });
    expect(readLabel('a violet cube')).toEqual({ colour: 'purple', kind: 'box' });
    expect(readLabel('green thing')).toEqual({ colour: 'green', kind: 'unknown' });
  });

  it('tells a colour outside the vocabulary from no colour at all', () => {
    expect(readLabel('white box')).toEqual({
      colour: undefined,
      otherColour: 'white',
      kind: 'box',
    });
    expect(readLabel('red box', ['blue'])).toEqual({
      colour: undefined,
      otherColour: 'red',
      kind: 'box',
    });
    expect(readLabel('chair')).toEqual({
      colour: undefined,
      otherColour: undefined,
      kind: 'unknown',
    });
    expect(readLabel('red pillar', COLOUR_NAMES, ['box'])).toEqual({
      colour: 'red',
      kind: 'unknown',
    });
  });
});

describe('replyText and jsonInText', () => {
  it('take the JSON out of structured output, a fenced block, or text around it', () => {
    const reply = (content: unknown) => ({ choices: [{ message: { content } }] });
    expect(jsonInText(replyText(reply('{"objects":[]}')))).toEqual({ objects: [] });
    expect(
      jsonInText(replyText(reply('Here:\n```json\n[{"label":"red box"}]\n```\nDone.'))),
    ).toEqual([{ label: 'red box' }]);
    expect(
      jsonInText(replyText(reply([{ type: 'text', text: 'I see {"objects": []} here' }]))),
    ).toEqual({
      objects: [],
    });
  });

  it('refuse a reply with no text, a refusal, or no JSON in it', () => {
    expect(() => replyText({ choices: [] })).toThrow(/no choices\[0\]\.message\.content/);
    expect(() => replyText({ choices: [{ message: { content: null, refusal: 'no' } }] })).toThrow(
      /refused: no/,
    );
    expect(() => jsonInText('I cannot see anything')).toThrow(/no JSON/);
    expect(() => replyEntries('{"things": 3}')).toThrow(/not \{"objects"/);
  });
});

describe('pixelBox', () => {
  it('turns corners into inclusive pixels, in either order, and per-mille into pixels', () => {
    expect(pixelBox([10, 20, 110, 120], 320, 240, 'pixels')).toEqual({
      box: { left: 10, top: 20, right: 109, bottom: 119 },
      clipped: false,
    });
    expect(pixelBox([110, 120, 10, 20], 320, 240, 'pixels')?.box).toEqual({
      left: 10,
      top: 20,
      right: 109,
      bottom: 119,
    });
    expect(pixelBox([250, 500, 500, 1000], 320, 240, 'per-mille')?.box).toEqual({
      left: 80,
      top: 120,
      right: 159,
      bottom: 239,
    });
  });

  it('cuts a box to the image, and has none for a box wholly outside it', () => {
    expect(pixelBox([-40, -5, 50, 300], 320, 240, 'pixels')).toEqual({
      box: { left: 0, top: 0, right: 49, bottom: 239 },
      clipped: true,
    });
    expect(pixelBox([400, 10, 500, 50], 320, 240, 'pixels')).toBeUndefined();
    expect(pixelBox([10, 10, 10.5, 50], 320, 240, 'pixels')).toBeUndefined();
  });
});

describe('readEntries', () => {
  it('keeps good entries, drops and counts malformed, other-coloured and outside ones', () => {
    const { detections, counts } = readEntries(
      [
        { label: 'red box', box: [10, 100, 60, 160], confidence: 0.9 },
        { label: 'blue pillar', bbox_2d: [200, 90, 230, 150], confidence: 80 },
        { label: 'green box', box: [300, 200, 400, 300] },
        { label: 'white box', box: [0, 0, 10, 10], confidence: 0.9 },
        { label: 'red box', box: [10, 100, 60] },
        { label: 'yellow box', box: [1000, 1000, 1100, 1100], confidence: 0.5 },
        'a red box',
        { box: [1, 2, 3, 4] },
      ],
      options,
    );
    expect(detections.map((d) => [d.colour, d.kind, d.confidence])).toEqual([
      ['red', 'box', 0.9],
      ['blue', 'pillar', 0.8],
      ['green', 'box', 0.5],
    ]);
    expect(detections[2]?.box).toEqual({ left: 300, top: 200, right: 319, bottom: 239 });
    expect(detections.every((d) => d.detector === 'vlm:test' && d.baseRows === undefined)).toBe(
      true,
    );
    expect(counts).toEqual({
      received: 8,
      kept: 3,
      malformed: 3,
      otherColour: 1,
      outside: 1,
      clipped: 1,
      beyondMax: 0,
    });
  });

  it('keeps only the most confident maxObjects', () => {
    const entries = [0.2, 0.9, 0.5].map((confidence, i) => ({
      label: 'red box',
      box: [i * 50, 100, i * 50 + 40, 150],
      confidence,
    }));
    const { detections, counts } = readEntries(entries, { ...options, maxObjects: 2 });
    expect(detections.map((d) => d.confidence)).toEqual([0.9, 0.5]);
    expect(counts.beyondMax).toBe(1);
    expect(counts.kept).toBe(2);
  });
});
