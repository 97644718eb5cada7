// `hal fleet run --record FILE`: one MCAP file for the whole fleet, each robot's calls, pose,
// camera, log, e-stops (and a physical robot's steps and link) on its own channels under
// `/<device>` (docs/recording.md), and the run itself in the metadata record `hal.fleet`.
import { recordHal, RECORDER_VERSION } from '@hal/recorder';
import type { RecorderStats } from '@hal/recorder';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { CliIO } from '../io.js';
import { cliLogger } from '../logger.js';
import { openRecordingFile } from '../output-place.js';

/** A fleet run being recorded. */
export interface FleetRecording {
  /** Records one device under its id (the device manager's `wrapDevice`). */
  wrapDevice(device: string, hal: HardwareAbstractionLayer): HardwareAbstractionLayer;
  /** Notes what the run was (mode, command, devices) in the metadata record `hal.fleet`. */
  describe(run: { mode: string; command: string; devices: string[] }): void;
  /** Finishes the file (after the devices are cleaned up, so their last records are in). */
  close(): Promise<RecorderStats & { file: string }>;
}

/** Opens `file` for a fleet run: USAGE, before any robot is touched, when it cannot be written. */
export async function startFleetRecording(
  file: string,
  io: CliIO,
  { json, overwrite }: { json: boolean; overwrite: boolean },
): Promise<FleetRecording> {
  const recorder = await openRecordingFile(
    { option: '--record', path: file, overwrite },
    { logger: cliLogger(io, json) },
  );
  const sampling = new AbortController();
  return {
    wrapDevice: (device, hal) =>
      recordHal(hal, recorder, { namespace: device, deviceId: device, signal: sampling.signal }),
    describe: (run) =>
      recorder.metadata('hal.fleet', {
        mode: run.mode,
        command: run.command,
        devices: JSON.stringify(run.devices),
        version: RECORDER_VERSION,
      }),
    close: async () => {
      sampling.abort();
      return { file, ...(await recorder.close()) };
    },
  };
}
