import type { RecordablePerception } from '@hal/recorder';
import type { Leash } from '@hal/tools';
import type { HardwareAbstractionLayer, Logger } from '@hal/types';

/** How {@link serveFoxglove} serves a HAL to Foxglove or Lichtblick. */
export interface FoxgloveServeOptions {
  /** Address to bind. Default 127.0.0.1; any non-loopback address needs `token`. */
  host?: string;
  /** TCP port; 0 picks a free one. Default 8765 (Foxglove's own default). */
  port?: number;
  /**
   * Shared secret (at least 16 characters). Clients present it as `?token=` in the URL they open
   * (`ws://robot:8765/?token=...`, which Foxglove and Lichtblick pass on as typed) or as a Bearer
   * token. With a token, whoever presents it may connect, from any page or program.
   */
  token?: string;
  /**
   * Web pages trusted without a token, as browsers send their origin (Foxglove's web app is
   * `https://app.foxglove.dev`). Pages served from this machine and the desktop apps (which send
   * no origin, or `file://`) are trusted; any other page is refused with HTTP 403.
   */
  allowedOrigins?: readonly string[];
  /**
   * Perception running on the robot (a @hal/perception `Perception`): after each look, its
   * sightings (`/perception/detections`) and remembered objects (`/perception/objects`) as
   * foxglove.SceneUpdate, and its grid (`/perception/grid`, foxglove.Grid) when it changed, as a
   * recording has them.
   */
  perception?: RecordablePerception;
  /** The leash on what a viewer drives (teleop): caps, geofence, approval. Default none. */
  leash?: Leash;
  /** Pose and /tf messages per second. Default 10. */
  poseRateHz?: number;
  /** Camera frames per second while a viewer subscribes to the camera. Default 2; 0: no camera. */
  cameraRateHz?: number;
  /** Wheel steps and link statistics per second (a physical robot). Default 1. */
  linkRateHz?: number;
  /**
   * How long one teleop message drives, ms: a viewer that stops publishing (or goes away) leaves
   * the robot stopped this long after its last message. Default 600 (100..2000).
   */
  teleopHoldMs?: number;
  /**
   * Bytes waiting to go to one viewer beyond which its messages are dropped (and counted) rather
   * than queued. Default 1 MiB.
   */
  maxQueuedBytes?: number;
  /** The robot's namespace (topics under `/<namespace>`, as a fleet recording has them). */
  namespace?: string;
  /** The device's id (the server's name in the viewer). Default the HAL's own. */
  deviceId?: string;
  logger?: Logger;
}

export const FOXGLOVE_DEFAULTS = {
  host: '127.0.0.1',
  port: 8765,
  poseRateHz: 10,
  cameraRateHz: 2,
  linkRateHz: 1,
  teleopHoldMs: 600,
  maxQueuedBytes: 1024 * 1024,
} as const;

/** What one viewer lost: messages dropped because it could not keep up, per topic. */
export interface ViewerDrops {
  client: string;
  dropped: number;
  byTopic: Record<string, number>;
}

/** Figures of a running live view. */
export interface FoxgloveStats {
  /** Viewers connected now. */
  clients: number;
  /** Messages handed to the sockets of the viewers connected now, by topic. */
  sent: Record<string, number>;
  /** Messages dropped for a slow viewer, in all. */
  dropped: number;
  /** The drops of each viewer connected now, and of the last 100 gone that lost any. */
  drops: ViewerDrops[];
  /** Teleop messages driven, and refused (leash, guard, e-stop). */
  teleop: { driven: number; refused: number };
}

/** What {@link serveFoxglove} returns. */
export interface FoxgloveLiveServer {
  /** Where it listens, e.g. `ws://127.0.0.1:8765`. */
  readonly url: string;
  readonly address: { host: string; port: number };
  /**
   * The served HAL with a tap: calls made through it (an agent's, an MCP client's) show in the
   * view at once: its log lines on the log topic, its e-stops and resets on the safety topic, the
   * frames it captures on the camera topic. Calls behave exactly as on the HAL itself.
   */
  readonly hal: HardwareAbstractionLayer;
  stats(): FoxgloveStats;
  /** Disconnects every viewer and stops listening. The HAL is left to its owner. */
  close(): Promise<void>;
}
