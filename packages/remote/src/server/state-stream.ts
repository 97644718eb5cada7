import { MESSAGE_SCHEMAS } from '../protocol.js';
import type { ServerState } from './server-state.js';

/**
 * Sends every subscribed client the robot's pose, whether a motion runs, the safety status and
 * its role, `stateRateHz` times a second. A tick still reading the pose when the next is due is
 * skipped; a client that cannot keep up skips states rather than growing a backlog.
 */
export function streamStates(state: ServerState): ReturnType<typeof setInterval> {
  const { hal, sessions, settings, out } = state;
  let streaming = false;
  return setInterval(() => {
    if (streaming) return;
    const subscribers = [...sessions.values()].filter((s) => s.subscribed);
    if (subscribers.length === 0) return;
    streaming = true;
    hal.locomotion
      .getPose()
      .then(
        (pose) => pose,
        () => null,
      )
      .then((pose) => {
        const safety = hal.safety.getSafetyStatus();
        const moving = [...sessions.values()].some((s) => s.running > 0);
        for (const session of subscribers) {
          if (session.socket.bufferedAmount > settings.maxMessageBytes) continue;
          out.send(session, MESSAGE_SCHEMAS.state, { pose, moving, safety, role: session.role });
        }
      })
      .finally(() => {
        streaming = false;
      });
  }, 1000 / settings.stateRateHz);
}
