import { describe, expect, it } from 'vitest';
import { memorySink } from './file-sink.js';
import type { PerceivedGrid, PerceivedObject } from './perception-messages.js';
import { readRecording } from './read-recording.js';
import { MAX_PENDING_LOOKS, PERCEPTION_TOPICS, recordPerception } from './record-perception.js';
import type { PerceivedLook, RecordablePerception } from './record-perception.js';
import { McapRecorder } from './recorder.js';
import { expectWellFormed } from './testing/well-formed.js';

const BOX: PerceivedObject = {
  id: 'red box 1',
  colour: 'red',
  kind: 'box',
  label: 'red box',
  x: 1,
  y: 0.5,
  uncertaintyM: 0.02,
  widthM: 0.2,
  timesSeen: 1,
  lastSeenAt: 1_700_000_000_000,
};

/** A perception that looks when told, remembering one box; its grid changes with every look. */
function fakePerception(): RecordablePerception & { look(): void; grid: PerceivedGrid } {
  const listeners = new Set<(look: PerceivedLook) => void>();
  let version = 0;
  const grid: PerceivedGrid = {
    spec: { width: 4, height: 2, resolutionM: 0.5, originX: -1, originY: -0.5 },
    get version() {
      return version;
    },
    stateOf: (cx, cy) => (cx === 3 && cy === 1 ? 'occupied' : cx < 2 ? 'free' : 'unknown'),
  };
  return {
    grid,
    memory: { all: () => [{ ...BOX }] },
    onLook(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    look() {
      version += 1;
      const sighting = {
        colour: 'red',
        kind: 'box',
        label: 'red box',
        bearingDeg: 26.6,
        distanceM: 1.12,
        widthM: 0.2,
        heightM: 0.3,
        confidence: 0.9,
        world: { x: 1, y: 0.5 },
        detector: 'colour',
      };
      for (const listener of listeners) {
        listener({ capturedAt: Date.now(), objects: [sighting], remembered: [{ ...BOX }] });
      }
    },
  };
}

describe('recordPerception', () => {
  it('writes a look later, never on its path, and skips (counting) looks beyond what may wait', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const perception = fakePerception();
    const recording = recordPerception(recorder, perception, { gridPeriodMs: 0 });
    const looks = MAX_PENDING_LOOKS + 24;
    // one turn of the event loop: nothing of it is written yet, and no look waits for it
    for (let i = 0; i < looks; i += 1) perception.look();
    expect(recorder.stats().written).toBe(0);
    expect(recording.looks).toBe(looks);
    expect(recording.skipped).toBe(24);
    await recorder.drained();
    perception.look();
    recording.stop();
    perception.look();
    await recorder.close();
    const read = await readRecording(sink.bytes());
    expectWellFormed(read);
    const objects = read.messages.filter((m) => m.topic === PERCEPTION_TOPICS.objects);
    expect(objects).toHaveLength(MAX_PENDING_LOOKS + 1);
    const last = objects.at(-1)!.value as {
      entities: Array<{ cubes: Array<{ size: object; pose: { position: object } }> }>;
    };
    // as wide as remembered, as tall as last seen, standing on the floor where it is
    expect(last.entities[0]!.cubes[0]).toMatchObject({
      size: { x: 0.2, y: 0.2, z: 0.3 },
      pose: { position: { x: 1, y: 0.5, z: 0.15 } },
    });
    const grid = read.messages.filter((m) => m.topic === PERCEPTION_TOPICS.grid).at(-1)!.value as {
      data: string;
      column_count: number;
    };
    expect(grid.column_count).toBe(4);
    expect([...Buffer.from(grid.data, 'base64')]).toEqual([0, 0, 255, 255, 0, 0, 255, 100]);
  });

  it('refuses a bad namespace or grid period', async () => {
    const recorder = await McapRecorder.create(memorySink());
    expect(() => recordPerception(recorder, fakePerception(), { namespace: 'a b' })).toThrow(
      /"namespace" must be/,
    );
    expect(() => recordPerception(recorder, fakePerception(), { gridPeriodMs: -1 })).toThrow(
      /"gridPeriodMs" must be 0 or more/,
    );
    await recorder.close();
  });
});
