import { FrameDecoder } from './frame-decoder.js';
import type { Frame, FrameError } from './frame.js';

/** One thing a {@link FrameDecoder} reported, as a test records it. */
export type RecordedEvent =
  | { kind: 'frame'; frame: Frame }
  | { kind: 'error'; error: FrameError; dropped: number }
  | { kind: 'garbage'; dropped: number }
  | { kind: 'oversize'; length: number };

/**
 * A decoder whose handlers record everything it reports, in order. `copy` keeps a copy of each
 * payload (as a caller that reuses its chunks must); by default the payloads are kept as handed
 * out, views, to test that contract. `blockBytes` is passed to the decoder.
 */
export function frameRecorder(options: { copy?: boolean; blockBytes?: number } = {}): {
  decoder: FrameDecoder;
  events: RecordedEvent[];
  frames: () => Frame[];
} {
  const events: RecordedEvent[] = [];
  const decoder = new FrameDecoder(
    {
      onFrame: (type, seq, payload) =>
        events.push({
          kind: 'frame',
          frame: { type, seq, payload: options.copy === true ? payload.slice() : payload },
        }),
      onError: (error, dropped) => events.push({ kind: 'error', error, dropped }),
      onGarbage: (dropped) => events.push({ kind: 'garbage', dropped }),
      onOversize: (length) => events.push({ kind: 'oversize', length }),
    },
    options.blockBytes,
  );
  const frames = () => events.flatMap((e) => (e.kind === 'frame' ? [e.frame] : []));
  return { decoder, events, frames };
}

/** The bytes of `parts`, one after another, in one array. */
export function concat(...parts: Uint8Array[]): Uint8Array {
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let at = 0;
  for (const p of parts) {
    out.set(p, at);
    at += p.length;
  }
  return out;
}
