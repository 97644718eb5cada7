// `hal eval --record DIR`: each trial kept as an MCAP recording (@hal/recorder's recordHal around
// the trial's HAL), at DIR/AGENT/GROUP/TASK/seed-S-trial-I.mcap. A simulated trial's recording
// runs on the simulator's clock (from the wall-clock time the trial began), so its timestamps
// and durations are the robot's, not the harness's.
import { mkdir } from 'node:fs/promises';
import { join } from 'node:path';
import type { InstrumentedHal, TrialInfo } from '@hal/eval';
import { GuardedHAL } from '@hal/perception';
import { recordHal } from '@hal/recorder';
import type { HardwareAbstractionLayer } from '@hal/types';
import { recordGuard } from '../guard-options.js';
import { openRecordingFile } from '../output-place.js';

/** A name safe as a folder: `local:SmolLM2` becomes `local-SmolLM2`. */
const folder = (name: string) => name.replace(/[^A-Za-z0-9._@-]+/g, '-');

/** Where a trial's recording goes, inside `dir`. */
export function recordingPath(
  dir: string,
  info: Pick<TrialInfo, 'task' | 'seed' | 'trial' | 'agent' | 'on'>,
): string {
  const agent = info.on === 'simulator' ? info.agent : `${info.agent}@${info.on}`;
  const [group, name] = info.task.id.split('/') as [string, string];
  return join(dir, folder(agent), group, name, `seed-${info.seed}-trial-${info.trial}.mcap`);
}

/** What the recordings of a run came to. */
export interface RecordedTrials {
  files: string[];
  /** Messages the recorders dropped, over all files (0 unless the disk was too slow). */
  dropped: number;
}

/** An `instrument` for runEval that records every trial into `dir`, and the tally. */
export function recordTrials(dir: string): {
  instrument: (hal: HardwareAbstractionLayer, info: TrialInfo) => Promise<InstrumentedHal>;
  recorded: RecordedTrials;
} {
  const recorded: RecordedTrials = { files: [], dropped: 0 };
  const instrument = async (
    hal: HardwareAbstractionLayer,
    info: TrialInfo,
  ): Promise<InstrumentedHal> => {
    const file = recordingPath(dir, info);
    await mkdir(join(file, '..'), { recursive: true });
    const epochNs = BigInt(Date.now()) * 1_000_000n;
    // the folder was checked before the run (new, empty, or --overwrite): a file there is replaced
    const recorder = await openRecordingFile(
      { option: '--record', path: file, overwrite: true },
      info.on === 'simulator'
        ? { clock: () => epochNs + BigInt(Math.round(info.nowUs())) * 1000n }
        : {},
    );
    // no periodic sampling: the simulator runs faster than any timer; the pose is recorded after
    // every motion
    const wrapped = recordHal(hal, recorder, { posePeriodMs: 0, map: info.variant.map });
    // the trial's guard (it is the HAL given, when on): its stops beside the calls
    if (hal instanceof GuardedHAL) recordGuard(hal, recorder);
    return {
      hal: wrapped,
      close: async () => {
        const stats = await recorder.close();
        recorded.files.push(file);
        recorded.dropped += stats.dropped;
      },
    };
  };
  return { instrument, recorded };
}
