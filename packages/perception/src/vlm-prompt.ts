import type { ChatMessage } from '@hal/agent';
import type { ColourName } from './palette.js';
import type { VlmKind } from './vlm-labels.js';
import type { VlmBoxUnits } from './vlm-reply.js';

/*
 * What a vision model is asked: the frame as an image, its size, the vocabulary, one box
 * convention stated in words, and JSON only, as structured output where the server supports it.
 */

/** How the reply's format is asked for: a JSON Schema, any JSON object, or only in the prompt. */
export type VlmResponseFormat = 'json_schema' | 'json_object' | 'none';

/** What the prompt needs to say. */
export interface VlmPromptOptions {
  width: number;
  height: number;
  units: VlmBoxUnits;
  colours: readonly ColourName[];
  kinds: readonly VlmKind[];
  maxObjects: number;
}

const KIND_WORDS: Readonly<Record<VlmKind, string>> = Object.freeze({
  box: 'box (flat faces and straight corners, a cube or crate)',
  pillar: 'pillar (an upright round cylinder)',
});

/** The JSON Schema of the answer, for `response_format: json_schema` (strict). */
export const VLM_REPLY_JSON_SCHEMA: Readonly<Record<string, unknown>> = Object.freeze({
  type: 'object',
  properties: {
    objects: {
      type: 'array',
      items: {
        type: 'object',
        properties: {
          label: { type: 'string', description: 'colour and kind, e.g. "red box"' },
          box: {
            type: 'array',
            items: { type: 'number' },
            description: '[x0, y0, x1, y1]: top-left and bottom-right corners',
          },
          confidence: { type: 'number', description: '0..1' },
        },
        required: ['label', 'box', 'confidence'],
        additionalProperties: false,
      },
    },
  },
  required: ['objects'],
  additionalProperties: false,
});

/** The instruction sent with the frame. */
export function vlmInstruction(options: VlmPromptOptions): string {
  const { width, height, units } = options;
  const coordinates =
    units === 'pixels'
      ? `in pixels of this ${width}x${height} image: x from 0 (left edge) to ${width} (right edge), ` +
        `y from 0 (top edge) to ${height} (bottom edge)`
      : 'normalised to 0..1000: x from 0 (left edge) to 1000 (right edge), y from 0 (top edge) to ' +
        '1000 (bottom edge), whatever the image size';
  return [
    "This is a frame from a small robot's camera, looking ahead over the floor.",
    `Find each distinct coloured object standing on the floor, at most ${options.maxObjects}, nearest first.`,
    `Label each as "<colour> <kind>": colour one of ${options.colours.join(', ')}` +
      ' (an object of another colour: name the colour you see);' +
      ` kind one of ${options.kinds.map((k) => KIND_WORDS[k]).join(', ')}` +
      ' (anything else: say what it is).',
    'Give its bounding box as [x0, y0, x1, y1], where (x0, y0) is the top-left corner and (x1, y1)' +
      ` the bottom-right corner, ${coordinates}.`,
    'The box must enclose all of the object that is visible, down to where it meets the floor.',
    'Give a confidence from 0 to 1.',
    "Ignore walls, the floor, the sky, shadows and the robot's own parts.",
    'Answer with JSON only, no other text: ' +
      '{"objects": [{"label": "red box", "box": [x0, y0, x1, y1], "confidence": 0.9}]}, ' +
      'or {"objects": []} when there is none.',
  ].join('\n');
}

/** The messages: the instruction and the frame (a `data:image/jpeg;base64,...` URL). */
export function vlmMessages(frame: string, options: VlmPromptOptions): ChatMessage[] {
  return [
    {
      role: 'user',
      content: [
        { type: 'text', text: vlmInstruction(options) },
        { type: 'image_url', image_url: { url: frame } },
      ],
    },
  ];
}

/** The chat-completions request body, with `response_format` as `format` asks. */
export function vlmRequestBody(
  settings: { model: string; temperature: number; maxTokens: number },
  messages: ChatMessage[],
  format: VlmResponseFormat,
): Record<string, unknown> {
  const body: Record<string, unknown> = {
    model: settings.model,
    messages,
    temperature: settings.temperature,
    max_tokens: settings.maxTokens,
  };
  if (format === 'json_schema') {
    body['response_format'] = {
      type: 'json_schema',
      json_schema: { name: 'detected_objects', schema: VLM_REPLY_JSON_SCHEMA, strict: true },
    };
  } else if (format === 'json_object') {
    body['response_format'] = { type: 'json_object' };
  }
  return body;
}
