// camera: frames on request, within the spec's interactive class.
import jpeg from 'jpeg-js';
import type { RunContext } from '../context.js';
import { describeAnswer } from '../context.js';
import { LATENCY_CLASSES } from '../spec.js';
import type { Check } from './check.js';
import { fail, pass } from './check.js';
import { expectError, formatVerdict, latencyVerdict, validReply } from './helpers.js';

const frame = (ctx: RunContext) =>
  ctx.ask(
    ctx.wire.subject('cameraFrame'),
    ctx.wire.envelope('hal/camera/frame/req/1.0', { format: 'jpeg' }),
    'frame',
  );

const JPEG_START = [0xff, 0xd8, 0xff];

/** The size of a JPEG as a decoder reads it (not as the reply claims), or undefined. */
function decodedSize(bytes: Uint8Array): { width: number; height: number } | undefined {
  try {
    const image = jpeg.decode(bytes, { maxMemoryUsageInMB: 64 });
    return { width: image.width, height: image.height };
  } catch {
    return undefined;
  }
}

export const CAMERA_CHECKS: readonly Check[] = [
  {
    capability: 'camera',
    group: 'timing',
    name: 'frame',
    title: 'camera.frame.req round trip',
    run: (ctx) =>
      latencyVerdict(
        ctx,
        Math.min(ctx.options.samples, 5),
        LATENCY_CLASSES.interactive,
        () => frame(ctx),
        validReply,
      ),
  },
  {
    capability: 'camera',
    group: 'format',
    name: 'frame-reply',
    title:
      'frame replies are valid envelopes holding a base64 JPEG of the width and height they state',
    run: async (ctx) => {
      const answer = await frame(ctx);
      const payload = answer.inspected?.payload;
      if (payload === undefined)
        return fail(`the frame request was answered ${describeAnswer(answer)}`);
      const bytes = Buffer.from(payload.data, 'base64');
      if (!JPEG_START.every((b, i) => bytes[i] === b)) return fail('the frame data is not a JPEG');
      const size = decodedSize(bytes);
      if (size === undefined) return fail('the frame data does not decode as a JPEG');
      if (size.width !== payload.width || size.height !== payload.height) {
        return fail(
          `the reply says ${payload.width}x${payload.height}, the JPEG is ${size.width}x${size.height}`,
        );
      }
      const verdict = formatVerdict(
        ctx.replies.filter((r) => r.kind === 'frame').map((r) => r.inspected),
        'frame replies',
      );
      return verdict.status === 'pass'
        ? pass(`${verdict.reason}; a ${bytes.length}-byte ${size.width}x${size.height} JPEG`)
        : verdict;
    },
  },
  {
    capability: 'camera',
    group: 'capability',
    name: 'works',
    title: 'an announced camera returns a frame, not an error',
    run: async (ctx) => {
      const answer = await frame(ctx);
      return answer.inspected?.payload !== undefined
        ? pass('a frame came back')
        : fail(`the frame request was answered ${describeAnswer(answer)}`);
    },
  },
  {
    capability: 'camera',
    group: 'capability',
    name: 'not-implemented',
    title: 'unannounced: camera.frame.req gets NOT_IMPLEMENTED (or no responder)',
    when: 'unannounced',
    run: async (ctx) => {
      const answer = await frame(ctx);
      const problem = expectError(answer, ['NOT_IMPLEMENTED'], true);
      return problem === undefined ? pass(describeAnswer(answer)) : fail(problem);
    },
  },
];
