// `hal test hal --device X --capability motor.differential`: the spec's compliance command.
import { Option } from 'commander';
import { CHECK_GROUPS, SPEC_CAPABILITIES } from '@hal/compliance';
import { addNatsOptions, deviceIdArg } from '../nats-options.js';
import { runTestHal } from '../test-hal/run-test-hal.js';
import { capabilityArg, groupArg, judgeArg, samplesArg } from '../test-hal/args.js';
import type { RegisterCommand } from './context.js';

export const registerTest: RegisterCommand = (program, ctx) => {
  const command = program
    .command('test')
    .description(
      'check a device on NATS against the Tafy HAL spec: message format, timing classes, error handling, capability accuracy, state consistency',
    )
    .argument('<suite>', 'what to test: "hal", as the spec writes it (hal test hal ...)')
    .option(
      '--device <id>',
      "the device to check (default: the spec's default device)",
      deviceIdArg,
    )
    .option(
      '--all',
      'check every device seen announcing its capabilities on NATS (listens 6 s), one after the other',
    )
    .addOption(
      new Option(
        '--capability <name>',
        `check only this capability (repeatable): ${SPEC_CAPABILITIES.join(', ')}; default all`,
      ).argParser(capabilityArg),
    )
    .addOption(
      new Option(
        '--group <name>',
        `run only this check group (repeatable): ${CHECK_GROUPS.join(', ')}; default all`,
      ).argParser(groupArg),
    )
    .option(
      '--mdns',
      "also check the device's mDNS announcement (_tafynode._tcp); on the device's network segment",
    )
    .option('--samples <n>', 'requests per latency measurement (default 20)', samplesArg)
    .option(
      '--judge <percentile>',
      'percentile held to the latency classes: p50 or p99 (default p50)',
      judgeArg,
    );
  addNatsOptions(command).action((suite: string, options) => runTestHal(ctx, suite, options));
};
