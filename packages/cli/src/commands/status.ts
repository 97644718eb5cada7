// `hal status`: one robot's identity, capabilities, pose, safety state and health; `--watch`
// streams updates at a rate until Ctrl-C.
import { Command, Option } from 'commander';
import { delay } from '@hal/types';
import { positiveArg } from '../values.js';
import { CliError } from '../cli-error.js';
import { emit } from '../io.js';
import { readStatus, statusLine, statusText } from '../status/snapshot.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import type { RegisterCommand } from './context.js';

interface StatusOptions extends TargetCliOptions {
  watch: boolean;
  rate: number;
}

const MAX_RATE_HZ = 50;

export const registerStatus: RegisterCommand = (program, { io, global }) => {
  const command = new Command('status')
    .description("show a robot's device info, capabilities, pose, safety state and health")
    .option('-w, --watch', 'keep printing updates until Ctrl-C', false)
    .addOption(
      new Option('--rate <hz>', `updates per second with --watch (at most ${MAX_RATE_HZ})`)
        .argParser(positiveArg('--rate'))
        .default(2),
    );
  addTargetOptions(command).action(async (options: StatusOptions) => {
    if (options.rate > MAX_RATE_HZ) {
      throw new CliError('USAGE', `"--rate" must be at most ${MAX_RATE_HZ} Hz`);
    }
    const target = resolveTarget(options, io.env);
    const connect =
      options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
    await withTarget(
      target,
      io,
      { ...connect, role: 'watch', json: global().json },
      async ({ hal, deviceId }) => {
        const first = await readStatus(hal, deviceId);
        emit(io, global(), first, () => statusText(first));
        if (!options.watch) return;
        const periodMs = 1000 / options.rate;
        for (;;) {
          await delay(periodMs, io.signal);
          if (io.signal.aborted) return;
          const next = await readStatus(hal, deviceId);
          emit(io, global(), next, () => statusLine(next));
        }
      },
    );
  });
  program.addCommand(command);
};
