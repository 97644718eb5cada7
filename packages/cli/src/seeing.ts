// Perception on the command line: where an agent or a network uses a robot with a camera
// (`hal agent`, `hal mcp`), its `scan` answers from what the robot can know, the range sensors
// and the camera through @hal/perception, and a recording keeps what it believed it saw.
import { Perception, withCameraScan } from '@hal/perception';
import { recordPerception } from '@hal/recorder';
import type { McapRecorder } from '@hal/recorder';
import { CAPABILITIES } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';

/** Targets reached over the network: they perceive where they are served. */
const SERVED_ELSEWHERE: ReadonlySet<string> = new Set(['ws', 'nats']);

/**
 * `hal` (the robot as the agent drives it: guarded, say) with its `scan` answered by the range
 * sensors and one camera look of `robot` (the robot itself: a look is a read), when `robot` has
 * a camera; its looks recorded on the perception topics of `recorder`. Unchanged for a robot with
 * no camera or one reached over the network.
 */
export function seeingFrom(
  hal: HardwareAbstractionLayer,
  robot: HardwareAbstractionLayer,
  recorder: McapRecorder | undefined,
  target?: { kind: string },
): { hal: HardwareAbstractionLayer; perception: Perception | undefined } {
  if (target !== undefined && SERVED_ELSEWHERE.has(target.kind)) {
    return { hal, perception: undefined };
  }
  if (!robot.getDeviceInfo().capabilities.includes(CAPABILITIES.camera)) {
    return { hal, perception: undefined };
  }
  const perception = new Perception(robot);
  if (recorder !== undefined) recordPerception(recorder, perception);
  return { hal: withCameraScan(hal, perception), perception };
}
