import type { McapRecorder, memorySink, RecorderStats } from '@hal/recorder';
import type { SimulationHAL } from '@hal/simulation';
import { withTimeout } from '@hal/types';

/** How often the page captures a camera frame into the recording, ms (2 frames a second). */
export const CAMERA_PERIOD_MS = 500;

/**
 * The longest `stop` waits for a camera frame still being captured, ms. A frame rendered in
 * software takes seconds on a loaded machine; one still out after this is left out of the file.
 */
export const CAPTURE_WAIT_MS = 5_000;

/** A finished recording, ready to download. */
export interface FinishedRecording {
  bytes: Uint8Array;
  stats: RecorderStats;
  fileName: string;
}

interface Active {
  hal: SimulationHAL;
  recorded: SimulationHAL;
  recorder: McapRecorder;
  sink: ReturnType<typeof memorySink>;
  stopSampling: AbortController;
  camera: ReturnType<typeof setInterval>;
  /** The camera frame being captured through the recorded HAL, if one is. */
  capturing: Promise<void> | undefined;
  /** Camera frames captured through the recorded HAL so far. */
  frames: number;
  startedAt: Date;
}

/**
 * Records the page's session into an MCAP file held in memory: the selected robot's HAL wrapped
 * with `recordHal`, so every call the page's panels make through it, its pose (every 100 ms and
 * after each motion) and its camera (a frame every {@link CAMERA_PERIOD_MS}, captured through
 * the recorded HAL) go into the file. Chunks are written uncompressed: the browser has no zstd
 * compressor (see zstd-browser.ts).
 */
export class SessionRecorder {
  readonly #cameraPeriodMs: number;
  readonly #captureWaitMs: number;
  #active: Active | undefined;
  #starting = false;

  constructor(options: { cameraPeriodMs?: number; captureWaitMs?: number } = {}) {
    this.#cameraPeriodMs = options.cameraPeriodMs ?? CAMERA_PERIOD_MS;
    this.#captureWaitMs = options.captureWaitMs ?? CAPTURE_WAIT_MS;
  }

  get recording(): boolean {
    return this.#active !== undefined;
  }

  /** Messages written and dropped so far (undefined when not recording). */
  stats(): RecorderStats | undefined {
    return this.#active?.recorder.stats();
  }

  /** Camera frames captured into the running recording (0 when none runs). */
  capturedFrames(): number {
    return this.#active?.frames ?? 0;
  }

  /** The HAL the page should call for `hal`: the recorded one while `hal` is being recorded. */
  halFor(hal: SimulationHAL): SimulationHAL {
    return this.#active?.hal === hal ? this.#active.recorded : hal;
  }

  /** Starts recording `hal` (already initialised) on map `mapName`. */
  async start(hal: SimulationHAL, mapName: string): Promise<void> {
    if (this.#active !== undefined || this.#starting) {
      throw new Error('a recording is already running');
    }
    this.#starting = true;
    try {
      this.#active = await this.#begin(hal, mapName);
    } finally {
      this.#starting = false;
    }
  }

  async #begin(hal: SimulationHAL, mapName: string): Promise<Active> {
    // the recorder is loaded with the first recording, not with the page
    const { McapRecorder, memorySink, recordHal } = await import('@hal/recorder');
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink, { compression: 'none' });
    const stopSampling = new AbortController();
    const recorded = recordHal(hal, recorder, {
      posePeriodMs: 100,
      map: { name: mapName },
      signal: stopSampling.signal,
    });
    const camera = setInterval(() => {
      if (active.capturing !== undefined) return;
      active.capturing = recorded.vision.captureFrame().then(
        () => {
          active.capturing = undefined;
          active.frames += 1;
        },
        () => (active.capturing = undefined),
      );
    }, this.#cameraPeriodMs);
    const active: Active = {
      hal,
      recorded,
      recorder,
      sink,
      stopSampling,
      camera,
      capturing: undefined,
      frames: 0,
      startedAt: new Date(),
    };
    return active;
  }

  /**
   * Ends the recording and hands back the file. A camera frame still being captured is waited
   * for (at most `captureWaitMs`), so the session's own last frame is in the file, not counted
   * as dropped; calls the page makes after this are no longer recorded.
   */
  async stop(): Promise<FinishedRecording> {
    const active = this.#active;
    if (active === undefined) throw new Error('no recording is running');
    this.#active = undefined;
    clearInterval(active.camera);
    if (active.capturing !== undefined) await withTimeout(active.capturing, this.#captureWaitMs);
    active.stopSampling.abort();
    const stats = await active.recorder.close();
    const stamp = active.startedAt.toISOString().replace(/[:.]/g, '-');
    return { bytes: active.sink.bytes(), stats, fileName: `hal-demo-${stamp}.mcap` };
  }
}
