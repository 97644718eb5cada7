// `hal record -o run.mcap STEPS...`: runs the steps on any robot the CLI names, recorded into an
// MCAP file (calls, pose, e-stops: docs/recording.md). A refused step is recorded and the run goes
// on, as a robot under test would; the summary says which.
import { Command } from 'commander';
import { recordHal } from '@hal/recorder';
import type { RecorderStats } from '@hal/recorder';
import { actionText, callFor } from '../drive/actions.js';
import { emit } from '../io.js';
import { cliLogger } from '../logger.js';
import { addOverwriteOption, openRecordingFile } from '../output-place.js';
import { parseStep } from '../record/steps.js';
import { addTargetOptions, describeTarget, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import type { RegisterCommand } from './context.js';

interface RecordOptions extends TargetCliOptions {
  output: string;
  overwrite?: boolean;
}

interface StepOutcome {
  step: string;
  success: boolean;
  code?: string;
}

export const registerRecord: RegisterCommand = (program, { io, global }) => {
  const command = new Command('record')
    .description('run steps on a robot and record the run to an MCAP file (see docs/recording.md)')
    .requiredOption('-o, --output <file>', 'the MCAP file to write')
    .argument(
      '<steps...>',
      'each one action: "forward DISTANCE", "turn ANGLE", "move-to X Y", "wheels L R MS", stop, "estop [REASON]", reset-estop; distances in metres or with a unit (10cm), angles in degrees or with a unit (1.5rad)',
    );
  addOverwriteOption(command, 'the -o file');
  addTargetOptions(command).action(async (stepTexts: string[], options: RecordOptions) => {
    const steps = stepTexts.map(parseStep);
    const target = resolveTarget(options, io.env);
    const json = global().json;
    const logger = cliLogger(io, json);
    // a file that cannot be written is refused (USAGE) before the robot is touched
    const recorder = await openRecordingFile(
      { option: '-o', path: options.output, overwrite: options.overwrite === true },
      { logger },
    );
    const connect =
      options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
    const outcomes: StepOutcome[] = [];
    const sampling = new AbortController();
    let stats: RecorderStats;
    try {
      await withTarget(target, io, { ...connect, json }, async ({ hal: opened, deviceId }) => {
        const map = target.kind === 'sim' ? { name: target.map } : undefined;
        const hal = recordHal(opened, recorder, {
          signal: sampling.signal,
          deviceId,
          ...(map ? { map } : {}),
        });
        for (const [i, action] of steps.entries()) {
          if (io.signal.aborted) break;
          const result = await callFor(hal, action);
          outcomes.push({
            step: stepTexts[i]!,
            success: result.success,
            ...(result.code === undefined ? {} : { code: result.code }),
          });
        }
        await hal.locomotion.getPose().catch(() => undefined);
        sampling.abort();
      });
    } finally {
      sampling.abort();
      stats = await recorder.close();
    }
    const summary = {
      file: options.output,
      target: describeTarget(target),
      steps: outcomes,
      recorder: stats,
    };
    emit(io, global(), summary, () =>
      [
        ...outcomes.map(
          (o, i) =>
            `${actionText(steps[i]!)}: ${o.success ? 'ok' : `refused (${o.code ?? 'failed'})`}`,
        ),
        `recorded ${stats.written} messages to ${options.output}${stats.dropped > 0 ? `, ${stats.dropped} dropped` : ''}`,
      ].join('\n'),
    );
  });
  program.addCommand(command);
};
