// `hal inspect run.mcap`: what a recording holds (duration, calls, errors, e-stops, the messages
// of each channel, what the recorder dropped), read with MCAP's recovery if it was cut short or
// damaged (and then where it stopped, and what it read). A file that is no recording is FAILED.
import { Command } from 'commander';
import { readRecordingFile, RecordingReadError, summarizeRecording } from '@hal/recorder';
import type { RecordingSummary } from '@hal/recorder';
import { errorMessage } from '@hal/types';
import { CliError } from '../cli-error.js';
import { emit } from '../io.js';
import type { RegisterCommand } from './context.js';

function summaryText(file: string, s: RecordingSummary): string {
  const robots = Object.keys(s.robots ?? {});
  const robot =
    s.robot !== undefined
      ? ` of ${s.robot['device_id']} (${s.robot['mode']})`
      : robots.length > 0
        ? ` of ${robots.length} robots (${robots.join(', ')})`
        : '';
  const width = Math.max(16, ...Object.keys(s.channels).map((topic) => topic.length));
  const codes = Object.entries(s.errorsByCode).map(([code, n]) => `${code} ${n}`);
  return [
    `${file}: a recording${robot}, ${s.durationS.toFixed(2)} s`,
    ...(s.truncation === undefined ? [] : [`not read whole: ${s.truncation}`]),
    `calls ${s.calls}, errors ${s.errors}${codes.length > 0 ? ` (${codes.join(', ')})` : ''}`,
    `emergency stops ${s.emergencyStops}, trips ${s.trips}${s.dropped === undefined ? '' : `, dropped ${s.dropped}`}`,
    ...Object.entries(s.robots ?? {}).map(
      ([id, r]) =>
        `  robot ${id}: calls ${r.calls}, errors ${r.errors}, emergency stops ${r.emergencyStops}, trips ${r.trips}, messages ${r.messages}`,
    ),
    ...Object.entries(s.channels).map(
      ([topic, c]) => `  ${topic.padEnd(width)} ${String(c.messages).padStart(7)}  ${c.schema}`,
    ),
  ].join('\n');
}

/**
 * Reads a recording for a command: NOT_FOUND when there is no such file; FAILED, with the
 * reader's reason (the file named in it), for one that is no recording: empty, not MCAP, no
 * header, or damaged with nothing readable.
 */
export async function readForCommand(file: string) {
  try {
    return await readRecordingFile(file);
  } catch (error) {
    if (error instanceof RecordingReadError) throw new CliError('FAILED', error.message);
    const code = (error as { code?: unknown }).code;
    if (code === 'ENOENT') throw new CliError('NOT_FOUND', `no recording at ${file}`);
    throw new CliError('FAILED', `cannot read ${file}: ${errorMessage(error)}`);
  }
}

export const registerInspect: RegisterCommand = (program, { io, global }) => {
  program.addCommand(
    new Command('inspect')
      .description(
        'sum up a recording: duration, calls, errors, e-stops, messages per channel (and per robot, for a fleet)',
      )
      .argument('<file>', 'an MCAP file written by hal record or @hal/recorder')
      .action(async (file: string) => {
        const summary = summarizeRecording(await readForCommand(file));
        emit(io, global(), { file, ...summary }, () => summaryText(file, summary));
      }),
  );
};
