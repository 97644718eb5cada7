// The statistics a wire binding keeps of its link to the robot. Only a binding with a link has
// them (PhysicalHAL's `transportStats()` and `linkStats()`); readers such as the recorder take
// them from any HAL by shape, so the shape is written here, once.

/** Round-trip statistics every transport keeps. */
export interface TransportStats {
  /** Requests sent, retries included. */
  sent: number;
  /** Replies that answered a pending request. */
  received: number;
  /** Requests given up after every attempt. */
  timeouts: number;
  /** Resends of a request (same bytes, same `seq`). */
  retries: number;
  /** Inbound messages dropped: undecodable, failed MAC, or answering no pending request. */
  dropped: number;
  /** Median round trip of answered requests, ms (from the attempt that was answered). */
  rttP50Ms: number;
  /** 99th percentile round trip, ms. */
  rttP99Ms: number;
}

/** Extra statistics of the serial link. */
export interface SerialLinkStats {
  framesSent: number;
  framesReceived: number;
  acksSent: number;
  acksReceived: number;
  /** Frames resent because their ACK did not come in time. */
  frameRetries: number;
  /** Frames given up after every attempt. */
  frameTimeouts: number;
  checksumErrors: number;
  /** Bytes skipped while hunting for a frame (garbage, bad headers). */
  resyncBytes: number;
  /** Duplicate DATA frames (same link seq) acknowledged but not delivered again. */
  duplicateFrames: number;
}
