// Perception's detections, remembered objects and grid, live: the recorder's own
// `recordPerception` (the same topics and foxglove.SceneUpdate / foxglove.Grid messages a
// recording has) writing into the live view instead of a file. It needs four things of a
// recorder (declare a channel, write a message, the clock, work deferred off the look's path),
// which the view gives here.
import { recordPerception } from '@hal/recorder';
import type {
  McapRecorder,
  NamedJsonSchema,
  PerceptionRecording,
  RecordablePerception,
} from '@hal/recorder';
import type { LivePublisher } from './publisher.js';

/** The part of McapRecorder that recordPerception uses, onto the live view's topics. */
interface PerceptionSink {
  channel(topic: string, schema: NamedJsonSchema): void;
  write(topic: string, value: unknown, logTime?: bigint): void;
  clock(): bigint;
  defer(task: () => void | PromiseLike<void>): void;
}

const nowNs = () => BigInt(Math.round((performance.timeOrigin + performance.now()) * 1e6));

/** Publishes `perception`'s looks on the view; stop() ends it. */
export function livePerception(
  publisher: LivePublisher,
  perception: RecordablePerception,
  namespace: string | undefined,
): PerceptionRecording {
  const sink: PerceptionSink = {
    channel: (topic, schema) => publisher.addTopic(topic, schema),
    write: (topic, value, logTime) => publisher.sendOn(topic, value, logTime ?? nowNs()),
    clock: nowNs,
    // after the look has answered its caller, as a recording does it
    defer: (task) =>
      void setImmediate(() => {
        void Promise.resolve()
          .then(task)
          .catch(() => undefined);
      }),
  };
  // recordPerception takes the recorder's class; the sink has every member it uses
  return recordPerception(
    sink as unknown as McapRecorder,
    perception,
    namespace === undefined ? {} : { namespace },
  );
}
