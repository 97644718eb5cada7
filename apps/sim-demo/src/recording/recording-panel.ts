import type { SimulationHAL } from '@hal/simulation';
import type { WorldScene } from '@hal/simulation/three';
import { errorMessage } from '@hal/types';
import { make } from '../dom.js';
import type { StatusLine } from '../status-line.js';
import { Playback } from './playback.js';
import { PlaybackRobot } from './playback-robot.js';
import { RecordingFileError } from './recording-file-error.js';
import type { SessionRecorder } from './session-recorder.js';

/*
 * The "Recording" card: "Record" records the selected robot's session into an MCAP file and
 * "Stop & download MCAP" saves it; "Open MCAP" plays a recording back in the scene (the recorded
 * robot at its recorded pose, the camera panel showing its recorded frames) with play/pause and
 * a time slider. While a recording plays, the live robots are hidden and not driven.
 */

export interface RecordingPanelOptions {
  /** The page's session recorder (main.ts routes the panels' calls through it). */
  sessions: SessionRecorder;
  scene: WorldScene;
  /** The selected robot's own HAL (the one recorded). */
  selectedHal: () => SimulationHAL;
  mapName: () => string;
  /** The robot camera card's canvas: the recorded frames are shown over it. */
  cameraCanvas: HTMLCanvasElement;
  status: StatusLine;
  /** Called as a playback starts (true) and ends (false): the page stops driving the robot. */
  onPlaybackChange: (playing: boolean) => void;
}

/** What the card shows, for the end-to-end test. */
export interface RecordingPanelState {
  recording: boolean;
  /** Messages written into the running recording (0 when none runs). */
  written: number;
  /** Camera frames captured into the running recording. */
  framesCaptured: number;
  message: string;
  playback: null | {
    name: string;
    durationMs: number;
    t: number;
    playing: boolean;
    poses: number;
    frames: number;
    calls: number;
    /** Where the scene draws the recorded robot now. */
    drawn: { x: number; y: number; yaw: number } | null;
    /** The recorded frame the camera panel shows now. */
    frameSrc: string | null;
  };
}

export class RecordingPanel {
  readonly sessions: SessionRecorder;
  readonly #options: RecordingPanelOptions;
  readonly #badge = make('span', { className: 'badge', id: 'recording-badge', textContent: 'OFF' });
  readonly #record = make('button', { id: 'record-button', textContent: 'Record' });
  readonly #file = make('input', {
    id: 'mcap-input',
    type: 'file',
    accept: '.mcap',
    ariaLabel: 'Open an MCAP recording',
  });
  readonly #toggle = make('button', { id: 'playback-toggle', className: 'secondary' });
  readonly #slider = make('input', {
    id: 'playback-slider',
    type: 'range',
    min: '0',
    step: 'any',
    ariaLabel: 'Playback time',
  });
  readonly #time = make('span', { id: 'playback-time', className: 'muted' });
  readonly #exit = make('button', {
    id: 'playback-exit',
    className: 'secondary',
    textContent: 'Back to live',
  });
  readonly #controls = make('div', { id: 'playback-controls', className: 'playback-controls' });
  readonly #message = make('p', { id: 'recording-message', className: 'recording-message' });
  readonly #frame = make('img', { id: 'playback-frame', alt: 'Recorded camera frame' });
  #playback: { player: Playback; robot: PlaybackRobot } | undefined;
  #frameSrc: string | null = null;
  /** The playback time last shown, and a count of the changes it made to the scene. */
  #shownT: number | undefined;
  #revision = 0;
  #busy = false;

  constructor(card: HTMLElement, options: RecordingPanelOptions) {
    this.#options = options;
    this.sessions = options.sessions;
    this.#controls.append(this.#toggle, this.#slider, this.#time, this.#exit);
    this.#controls.hidden = true;
    const open = make('label', { className: 'file-button' }, 'Open MCAP', this.#file);
    card.append(
      make('h2', {}, 'Recording ', this.#badge),
      make('div', { className: 'recording-actions' }, this.#record, open),
      this.#controls,
      this.#message,
    );
    this.#frame.hidden = true;
    options.cameraCanvas.after(this.#frame);
    this.#record.addEventListener('click', () => void this.#toggleRecording());
    this.#file.addEventListener('change', () => void this.#openFile());
    this.#toggle.addEventListener('click', () => this.#togglePlay());
    this.#slider.addEventListener('input', () => {
      this.#playback?.player.seek(Number(this.#slider.value));
      this.#show();
    });
    this.#exit.addEventListener('click', () => this.#endPlayback());
    this.#render();
  }

  /** Whether a recording is being played back (the live robots are not driven meanwhile). */
  get playingBack(): boolean {
    return this.#playback !== undefined;
  }

  get state(): RecordingPanelState {
    const playback = this.#playback;
    return {
      recording: this.sessions.recording,
      written: this.sessions.stats()?.written ?? 0,
      framesCaptured: this.sessions.capturedFrames(),
      message: this.#message.textContent ?? '',
      playback:
        playback === undefined
          ? null
          : {
              name: playback.player.timeline.name,
              durationMs: playback.player.timeline.durationMs,
              t: playback.player.t,
              playing: playback.player.playing,
              poses: playback.player.timeline.poses.length,
              frames: playback.player.timeline.frames.length,
              calls: playback.player.timeline.calls,
              drawn: playback.robot.drawnPose() ?? null,
              frameSrc: this.#frameSrc,
            },
    };
  }

  /** Once per animation frame: moves a playback on and draws it. */
  /** Counts the moves of the played-back robot: the scene needs drawing when it changes. */
  get revision(): number {
    return this.#revision;
  }

  frame(now: number): void {
    const playback = this.#playback;
    if (playback === undefined) return;
    const wasPlaying = playback.player.playing;
    playback.player.tick(now);
    this.#show();
    if (wasPlaying && !playback.player.playing) this.#render();
  }

  async #toggleRecording(): Promise<void> {
    if (this.#busy) return;
    this.#busy = true;
    try {
      if (this.sessions.recording) await this.#finishRecording();
      else {
        const hal = this.#options.selectedHal();
        await this.sessions.start(hal, this.#options.mapName());
        this.#say(
          `Recording ${hal.getDeviceInfo().id} (only this robot): drive it, then "Stop & download MCAP".`,
        );
      }
    } catch (error) {
      this.#say(`The recording failed: ${errorMessage(error)}`, true);
    } finally {
      this.#busy = false;
      this.#render();
    }
  }

  async #finishRecording(): Promise<void> {
    const { bytes, stats, fileName } = await this.sessions.stop();
    const url = URL.createObjectURL(
      new Blob([bytes.slice().buffer], { type: 'application/octet-stream' }),
    );
    const link = make('a', { href: url, download: fileName });
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60_000);
    const lost = stats.dropped > 0 ? `, ${stats.dropped} dropped` : '';
    this.#say(`Saved ${fileName}: ${stats.written} messages${lost}, ${kib(bytes.byteLength)}.`);
  }

  async #openFile(): Promise<void> {
    const file = this.#file.files?.[0];
    this.#file.value = ''; // the same file can be opened again
    if (file === undefined || this.#busy) return;
    if (this.sessions.recording) {
      this.#say('Stop the recording before opening a file.', true);
      return;
    }
    this.#busy = true;
    try {
      // the MCAP reader is loaded with the first file opened, not with the page
      const { readTimeline } = await import('./read-timeline.js');
      const timeline = await readTimeline(file.name, new Uint8Array(await file.arrayBuffer()));
      this.#endPlayback();
      const robot = new PlaybackRobot(timeline.poses);
      this.#playback = { player: new Playback(timeline), robot };
      this.#options.scene.robotsVisible = false;
      this.#options.cameraCanvas.style.visibility = 'hidden';
      this.#options.scene.scene.add(robot.group);
      this.#options.onPlaybackChange(true);
      this.#slider.max = String(timeline.durationMs);
      const cut =
        timeline.truncation !== undefined ? ` Not read whole: ${timeline.truncation}.` : '';
      this.#say(
        `${timeline.name}: ${seconds(timeline.durationMs)}, ${timeline.poses.length} poses, ` +
          `${timeline.frames.length} camera frames, ${timeline.calls} calls.${cut}`,
      );
      this.#options.status.set(`Playing back ${timeline.name}: the live robots are not driven`);
      this.#show();
    } catch (error) {
      this.#say(
        error instanceof RecordingFileError
          ? error.message
          : `Could not read ${file.name}: ${errorMessage(error)}`,
        true,
      );
    } finally {
      this.#busy = false;
      this.#render();
    }
  }

  #togglePlay(): void {
    const player = this.#playback?.player;
    if (player === undefined) return;
    if (player.playing) player.pause();
    else player.play();
    this.#render();
  }

  #endPlayback(): void {
    const playback = this.#playback;
    if (playback === undefined) return;
    this.#playback = undefined;
    this.#shownT = undefined;
    this.#options.scene.scene.remove(playback.robot.group);
    playback.robot.dispose();
    this.#options.scene.robotsVisible = true;
    this.#options.cameraCanvas.style.visibility = '';
    this.#frame.hidden = true;
    this.#frameSrc = null;
    this.#options.onPlaybackChange(false);
    this.#options.status.set('Back to the live robots');
    this.#render();
  }

  /** Draws the playback's current time: the robot, the camera frame, the slider. */
  #show(): void {
    const playback = this.#playback;
    if (playback === undefined) return;
    const view = playback.player.view();
    if (view.t !== this.#shownT) {
      this.#shownT = view.t;
      this.#revision += 1;
    }
    playback.robot.show(view.pose);
    const src = view.frame?.src ?? null;
    if (src !== this.#frameSrc) {
      this.#frameSrc = src;
      if (src !== null) this.#frame.src = src;
      this.#frame.hidden = src === null;
    }
    this.#slider.value = String(view.t);
    this.#time.textContent = `${seconds(view.t)} / ${seconds(playback.player.timeline.durationMs)}`;
  }

  #render(): void {
    const recording = this.sessions.recording;
    const playing = this.#playback !== undefined;
    this.#badge.textContent = recording ? 'REC' : playing ? 'PLAYBACK' : 'OFF';
    this.#badge.className = `badge${recording ? ' bad' : playing ? ' ok' : ''}`;
    this.#record.textContent = recording ? 'Stop & download MCAP' : 'Record';
    this.#record.disabled = playing || this.#busy;
    this.#file.disabled = recording;
    this.#controls.hidden = !playing;
    this.#toggle.textContent = this.#playback?.player.playing ? 'Pause' : 'Play';
  }

  #say(text: string, bad = false): void {
    this.#message.textContent = text;
    this.#message.className = `recording-message${bad ? ' bad' : ''}`;
    this.#message.role = bad ? 'alert' : 'status';
  }
}

function seconds(ms: number): string {
  return `${(ms / 1000).toFixed(1)} s`;
}

function kib(bytes: number): string {
  return `${(bytes / 1024).toFixed(0)} KiB`;
}
