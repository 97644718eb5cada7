import type { HardwareAbstractionLayer } from '@hal/types';
import { period } from './call-values.js';
import { interceptCalls } from './call-interceptor.js';
import type { CallHooks } from './call-interceptor.js';
import { CallRecords } from './call-records.js';
import type { CallEntry } from './call-records.js';
import { HalSampler, safe } from './hal-sampler.js';
import { linkTelemetry } from './link-telemetry.js';
import { robotNamespace } from './namespace.js';
import type { RecordHalOptions } from './record-hal-options.js';
import type { McapRecorder } from './recorder.js';
import { robotTopicWriter } from './robot-topics.js';

/** The version written into recordings. */
export const RECORDER_VERSION = '0.1.0';

const SUBSYSTEMS = ['locomotion', 'vision', 'manipulation', 'communication', 'safety'] as const;

/**
 * Wraps `hal` so that everything passing through it is recorded into `recorder`, and otherwise
 * behaves exactly as `hal` does: the same results, the same errors, synchronous calls still
 * synchronous. Every method of the HAL and of its subsystems is wrapped generically (no list of
 * calls), so a call added to the HAL is recorded with no change here.
 *
 * Recorded: every call (`/hal/calls`), the pose at `posePeriodMs` and after every locomotion,
 * manipulation or safety action (`/hal/pose`, `/tf`, `/hal/pose/raw`), camera frames
 * (`/hal/camera`), log lines (`/hal/log`), e-stops, resets and trips (`/hal/safety`), for a
 * physical robot its reported step counters (`/hal/steps`) and link statistics (`/hal/link`),
 * and the robot's metadata (`hal.robot`) once it is ready. With `namespace`, all of it goes under
 * `/<namespace>` (several robots in one file). A call answers its caller first: only its times,
 * the latch and (after an action that can move) the pose are read at once; the record is made
 * later, in a moment with no call on its way, logged at the time the call answered, and queued,
 * never waiting for the disk.
 */
export function recordHal<T extends HardwareAbstractionLayer>(
  hal: T,
  recorder: McapRecorder,
  options: RecordHalOptions = {},
): T {
  const posePeriodMs = period('posePeriodMs', options.posePeriodMs ?? 100);
  const linkPeriodMs = period('linkPeriodMs', options.linkPeriodMs ?? 1000);
  const space = robotNamespace(options.namespace);
  const telemetry = linkTelemetry(hal);
  // a physical robot's own reports (a HAL without them records neither topic)
  const write = robotTopicWriter(recorder, space, {
    steps: telemetry.steps !== undefined,
    link: telemetry.link !== undefined,
  });
  const sampler = new HalSampler(hal, recorder, write, telemetry, {
    posePeriodMs,
    linkPeriodMs,
    deviceId: options.deviceId,
    version: options.version ?? RECORDER_VERSION,
    map: options.map,
    signal: options.signal,
  });
  const records = new CallRecords(hal, recorder, write, sampler, options.logger);
  const hooks: CallHooks<CallEntry> = {
    started: (info) => records.started(info),
    answered(_info, call, outcome, value) {
      records.answered(call, outcome, value);
    },
  };
  // a HAL handed over already initialised (as the `hal` command opens its targets)
  if (safe(() => hal.isReady(), false)) sampler.onReady();
  return interceptCalls(hal, SUBSYSTEMS, hooks);
}
